#include "core/selection/selection_inputs.h"

#include "core/selection/triangle_error.h"

namespace triwalk {

SelectionInputKeeper::SelectionInputKeeper(const std::filesystem::path& datasetDirectory, glm::ivec2 fullSize)
    : errorWidth_(selectionErrorDefaults(fullSize).width),
      warp_(selectionErrorDefaults(fullSize).synthesis.warp),
      panoramas_(datasetDirectory, fullSize),
      meshes_(datasetDirectory) {}

void SelectionInputKeeper::keep(const ViewRecord& view, bool isSample, const Panorama& full) {
  const Panorama copy = panoramas_.keep(view, full, errorWidth_);
  if (isSample) meshes_.source(view, copy, warp_);
}

}  // namespace triwalk
