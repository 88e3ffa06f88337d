#pragma once
// What render and view share: the selection's mesh (or the dense
// triangulation when no selection is given) and the eye height.

#include "core/geometry/view_mesh.h"
#include "core/io/dataset.h"

#include <string>

namespace triwalk {

ViewMesh walkthroughMesh(const Dataset& dataset, const std::string& selectionPath);

// "N of M samples lie outside every view triangle, up to D m from one ...",
// or empty when every sample is covered: how much of the walkthrough is
// synthesized from a triangle the walker stands outside of.
std::string describeSamplesOutsideTriangles(const Dataset& dataset, const ViewMesh& mesh);

// Mean height of the samples: where the camera walks.
float sampleEyeHeight(const Dataset& dataset);

// "1280x720" -> width, height; throws InputError naming the option.
void parseSize(const std::string& text, const std::string& option, int& width, int& height);

}  // namespace triwalk
