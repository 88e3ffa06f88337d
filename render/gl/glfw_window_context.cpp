#include "render/gl/glfw_window_context.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

namespace triwalk {

namespace {

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

}  // namespace

GlfwWindowContext::GlfwWindowContext(int width, int height, const char* title, bool visible) {
  if (!glfwInit()) throw GlUnavailable("GLFW: cannot initialize (is there a display? " + lastGlfwError() + ")");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
  if (!window_) {
    const std::string error = lastGlfwError();
    glfwTerminate();
    throw GlUnavailable("GLFW: cannot open an OpenGL 4.5 core window: " + error);
  }
  makeCurrent();
  glfwSwapInterval(0);  // llvmpipe: do not wait for vertical sync
  initializeGlFunctions(reinterpret_cast<GlResolver>(glfwGetProcAddress), "GLFW");
}

GlfwWindowContext::~GlfwWindowContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwWindowContext::makeCurrent() { glfwMakeContextCurrent(window_); }

void GlfwWindowContext::swapBuffers() { glfwSwapBuffers(window_); }

bool GlfwWindowContext::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }

void GlfwWindowContext::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

}  // namespace triwalk
