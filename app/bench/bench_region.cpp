#include "app/bench/bench_groups.h"
#include "core/support/errors.h"
#include "render/capture/walkable_area.h"
#include "render/scene/assimp_scene.h"

namespace triwalk {

void benchRegion(BenchTable& table, const std::filesystem::path& scenePath) {
  if (!std::filesystem::exists(scenePath)) {
    throw InputError(scenePath.string(), "the region figure searches this scene; install assimp-testmodels");
  }
  ImportReport report;
  const Scene scene = importScene(scenePath, ImportOptions{}, report);
  RegionSearchOptions options;
  options.quiet = true;
  const auto start = BenchClock::now();
  const WalkableRegionProposal proposal = proposeWalkableRegion(scene, options, scenePath.string());
  const double seconds = secondsSince(start);
  table.add({"automatic walkable region (flood fill of 32x16 probes)",
             scenePath.filename().string() + ", " + std::to_string(scene.triangleCount()) + " triangles, " +
                 formatNumber(options.cellSize, 2) + " m cells",
             formatNumber(seconds, 1) + " s",
             std::to_string(proposal.probedCells) + " cells probed (" + formatNumber(proposal.probedCells / seconds, 0) +
                 "/s), " + formatNumber(proposal.region.area(), 1) + " m2 in " + std::to_string(proposal.parts) + " part(s)"});
}

}  // namespace triwalk
