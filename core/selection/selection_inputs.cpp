#include "core/selection/selection_inputs.h"

namespace triwalk {

SelectionInputKeeper::SelectionInputKeeper(const std::filesystem::path& datasetDirectory, glm::ivec2 fullSize)
    : defaults_(selectionErrorDefaults(fullSize)),
      panoramas_(datasetDirectory, fullSize),
      meshes_(datasetDirectory) {}

void SelectionInputKeeper::keep(const ViewRecord& view, bool isSample, const Panorama& full) {
  const Panorama copy = panoramas_.keep(view, full, defaults_.width);
  if (isSample) meshes_.source(view, copy, defaults_.synthesis.warp);
}

}  // namespace triwalk
