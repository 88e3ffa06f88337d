#pragma once
// Walking: W/S or Up/Down move along the view, A/D or Left/Right step
// sideways, Shift runs; dragging with the left or right mouse button on
// the view looks around. Input ImGui wants is left to ImGui. The person
// stays inside the area the triangulation covers (sliding along its edge).

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

// Moves from `from` by `step` in x, y, staying inside the mesh: the full
// step if its end is covered, else the covered component, else none.
glm::vec3 constrainedStep(const ViewMesh& mesh, glm::vec3 from, glm::vec2 step);

}  // namespace triwalk
