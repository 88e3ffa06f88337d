#include "app/viewer/walk_controller.h"

#include "core/geometry/walk_constraint.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

namespace triwalk {

void WalkController::update(GLFWwindow* window, double seconds, bool keyboardFree, bool mouseFree, const ViewMesh& mesh,
                            WalkState& state) {
  if (keyboardFree) {
    auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
    const float forward = float(down(GLFW_KEY_W) || down(GLFW_KEY_UP)) - float(down(GLFW_KEY_S) || down(GLFW_KEY_DOWN));
    const float sideways = float(down(GLFW_KEY_D) || down(GLFW_KEY_RIGHT)) - float(down(GLFW_KEY_A) || down(GLFW_KEY_LEFT));
    if (forward != 0.0f || sideways != 0.0f) {
      const float yaw = glm::radians(state.yawDegrees);
      const glm::vec2 ahead(std::cos(yaw), std::sin(yaw)), right(std::sin(yaw), -std::cos(yaw));
      const float run = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT) ? 3.0f : 1.0f;
      const glm::vec2 step = glm::normalize(forward * ahead + sideways * right) * state.speed * run * float(seconds);
      state.position = constrainedStep(mesh, state.position, step);
    }
  }
  const bool pressed = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS ||
                       glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  if (pressed && (dragging_ || mouseFree)) {
    if (dragging_) {
      state.yawDegrees -= float(x - lastX_) * 0.2f;
      state.pitchDegrees = std::clamp(state.pitchDegrees - float(y - lastY_) * 0.2f, -85.0f, 85.0f);
    }
    dragging_ = true;
  } else {
    dragging_ = false;
  }
  lastX_ = x;
  lastY_ = y;
  state.yawDegrees = std::fmod(state.yawDegrees + 360.0f, 360.0f);
}

}  // namespace triwalk
