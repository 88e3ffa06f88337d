#pragma once
// The third GL context: a GLFW window (the viewer). Needs a display (an X
// server, Xvfb in tests); GlUnavailable says so when there is none.

#include "render/gl/gl_context.h"

struct GLFWwindow;

namespace triwalk {

class GlfwWindowContext final : public GlContext {
public:
  GlfwWindowContext(int width, int height, const char* title, bool visible = true);
  ~GlfwWindowContext() override;
  GlfwWindowContext(const GlfwWindowContext&) = delete;
  GlfwWindowContext& operator=(const GlfwWindowContext&) = delete;

  std::string backendName() const override { return "GLFW window"; }
  void makeCurrent() override;
  GLFWwindow* window() const { return window_; }
  void swapBuffers();
  bool shouldClose() const;
  void framebufferSize(int& width, int& height) const;

private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace triwalk
