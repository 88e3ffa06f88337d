#pragma once
// Where a walker may stand: inside the walkable region (the floor the
// capture's samples cover) or on a view triangle. Outside every triangle a
// frame is synthesized from the best-ranked one (ViewMesh::locate), as a
// probe there is judged; a selection of a level of corridors leaves most of
// it outside its triangles (a loop cut open, a boundary that shrank), and a
// walker kept on the triangles could not reach those parts at all.

#include "core/geometry/view_mesh.h"

#include <glm/glm.hpp>

namespace triwalk {

bool isWalkable(const ViewMesh& mesh, glm::dvec2 point);

// Moves from `from` by `step` in x, y, staying where isWalkable: the full
// step if its end is walkable, else the walkable component (sliding along
// a wall), else none.
glm::vec3 constrainedStep(const ViewMesh& mesh, glm::vec3 from, glm::vec2 step);

}  // namespace triwalk
