#include "app/bench/bench_groups.h"
#include "core/support/errors.h"
#include "render/capture/walkable_area.h"

namespace triwalk {

void benchRegion(BenchTable& table, const std::string& sceneSpec, const SceneImportArguments& import) {
  if (sceneSpec != "builtin" && !std::filesystem::exists(sceneSpec)) {
    throw InputError(sceneSpec,
                     "the region figure searches this scene (--region-scene; the default comes with "
                     "assimp-testmodels)");
  }
  const LoadedScene loaded = loadSceneForCapture(sceneSpec, import);
  RegionSearchOptions options;
  options.quiet = true;
  const auto start = BenchClock::now();
  const WalkableRegionProposal proposal = proposeWalkableRegion(loaded.scene, options, sceneSpec);
  const double seconds = secondsSince(start);
  table.add({"automatic walkable region (flood fill of 32x16 probes)",
             loaded.name + ", " + std::to_string(loaded.scene.triangleCount()) + " triangles, " +
                 formatNumber(options.cellSize, 2) + " m cells",
             formatNumber(seconds, 1) + " s",
             std::to_string(proposal.probedCells) + " cells probed (" +
                 formatNumber(proposal.probedCells / seconds, 0) + "/s), " + formatNumber(proposal.region.area(), 1) +
                 " m2 in " + std::to_string(proposal.parts) + " part(s)"});
}

}  // namespace triwalk
