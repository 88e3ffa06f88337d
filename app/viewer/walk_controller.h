#pragma once
// Walking: W/S or Up/Down move along the view, A/D or Left/Right step
// sideways, Shift runs; dragging with the left or right mouse button on
// the view looks around. Input ImGui wants is left to ImGui. The person
// stays where core/geometry/walk_constraint.h allows (sliding along walls).

#include "core/geometry/view_mesh.h"

#include <glm/glm.hpp>

struct GLFWwindow;

namespace triwalk {

struct WalkState {
  glm::vec3 position{0.0f};
  float yawDegrees = 0.0f;
  float pitchDegrees = 0.0f;
  float speed = 1.2f;  // metres per second
};

class WalkController {
public:
  // keyboardFree / mouseFree: ImGui does not want that input now.
  void update(GLFWwindow* window, double seconds, bool keyboardFree, bool mouseFree, const ViewMesh& mesh, WalkState& state);

private:
  bool dragging_ = false;
  double lastX_ = 0.0, lastY_ = 0.0;
};

}  // namespace triwalk
