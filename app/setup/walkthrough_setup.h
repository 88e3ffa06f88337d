#pragma once
// What render and view share: the selection's mesh (or the dense
// triangulation when no selection is given) and the eye height.

#include "core/geometry/view_mesh.h"
#include "core/io/dataset.h"

#include <string>

namespace triwalk {

ViewMesh walkthroughMesh(const Dataset& dataset, const std::string& selectionPath);

// Mean height of the samples: where the camera walks.
float sampleEyeHeight(const Dataset& dataset);

// "1280x720" -> width, height; throws InputError naming the option.
void parseSize(const std::string& text, const std::string& option, int& width, int& height);

}  // namespace triwalk
