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

// Teleporting from reference to reference: the mesh's vertex nearest to
// `from` (further than 10 cm) among those within 60 degrees of the
// direction yawDegrees (x axis 0, counter-clockwise), or, if none is, within
// 90 degrees; -1 if there is none on that side.
int nearestVertexAhead(const ViewMesh& mesh, glm::dvec2 from, double yawDegrees);

}  // namespace triwalk
