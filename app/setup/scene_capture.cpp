#include "app/setup/scene_capture.h"

#include "render/capture/walkable_area.h"
#include "core/io/dataset.h"
#include "core/support/errors.h"
#include "render/gl/gl_context.h"

#include <cstdio>

namespace triwalk {

void announceReplacedDataset(const std::filesystem::path& out, const char* command) {
  if (!std::filesystem::exists(out / kManifestFileName)) return;
  std::string held = "a data set";
  try {
    const Dataset earlier = Dataset::open(out);
    held += " of " + std::to_string(earlier.sampleCount()) + " samples (scene " + earlier.manifest().scene + ")";
  } catch (const InputError&) {
    held += " (its manifest unreadable)";
  }
  std::printf("%s holds %s: this %s replaces it once complete\n", out.c_str(), held.c_str(), command);
  std::fflush(stdout);
}

CaptureSummary captureScene(const SceneCaptureRequest& request) {
  announceReplacedDataset(request.out, "capture");
  LoadedScene loaded = loadSceneForCapture(request.scene, request.import);
  auto context = createHeadlessContext(parseHeadlessBackend(request.gl));
  CaptureOptions options = request.options;
  options.sceneSource = sceneSource(request.scene, request.import);
  if (!options.area && !options.region && !request.autoArea && loaded.region) {
    options.region = loaded.region;
    if (!request.densityGiven && loaded.sampleSpacing) options.spacing = *loaded.sampleSpacing;
  } else if (!options.area && !options.region && (request.autoArea || loaded.imported)) {
    RegionSearchOptions search;
    search.eyeHeight = options.eyeHeight.value_or(loaded.scene.walkableArea.eyeHeight);
    search.starts = request.starts;
    search.quiet = options.quiet;
    WalkableRegionProposal proposal = proposeWalkableRegion(loaded.scene, search, request.scene);
    std::printf("%s\n", proposal.reason.c_str());
    options.region = std::move(proposal.region);
    loaded.scene.walkableArea.floorHeight = proposal.floorZ;
    loaded.scene.walkableArea.eyeHeight = search.eyeHeight;
  } else if (options.region && loaded.imported) {
    loaded.scene.walkableArea.floorHeight = floorHeightUnder(loaded.scene, *options.region);
  }
  const CapturePlan plan = planCapture(loaded.scene, options);
  if (plan.region) {
    std::printf("scene %s: %zu triangles; %zu samples %.2f m apart over a %.1f m2 region, at z = %.2f m, %d probes, %dx%d\n",
                loaded.name.c_str(), loaded.scene.triangleCount(), plan.samples.size(), plan.spacing, plan.region->area(),
                plan.eyeZ, options.probes, options.width, options.width / 2);
  } else {
    std::printf("scene %s: %zu triangles; %d paths x %d samples over [%.2f, %.2f] x [%.2f, %.2f] m at z = %.2f m, "
                "%d probes, %dx%d\n",
                loaded.name.c_str(), loaded.scene.triangleCount(), plan.paths, plan.perPath, plan.area.x, plan.area.z,
                plan.area.y, plan.area.w, plan.eyeZ, options.probes, options.width, options.width / 2);
  }
  const CaptureSummary summary = captureDataset(loaded.scene, loaded.name, options, request.out);
  std::printf("captured %d samples and %d probes into %s in %.1f s (%.2f panoramas/s) with %s\n", summary.samples,
              summary.probes, request.out.c_str(), summary.seconds,
              double(summary.samples + summary.probes) / std::max(summary.seconds, 1e-9), context->description().c_str());
  return summary;
}

}  // namespace triwalk
