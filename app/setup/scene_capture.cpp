#include "app/setup/scene_capture.h"

#include "render/capture/walkable_area.h"
#include "render/gl/gl_context.h"

#include <cstdio>

namespace triwalk {

CaptureSummary captureScene(const SceneCaptureRequest& request) {
  LoadedScene loaded = loadSceneForCapture(request.scene, request.import);
  auto context = createHeadlessContext(parseHeadlessBackend(request.gl));
  if (request.autoArea || (loaded.imported && !request.options.area)) {
    const float eyeHeight = request.options.eyeHeight.value_or(loaded.scene.walkableArea.eyeHeight);
    const WalkableAreaProposal proposal = proposeWalkableArea(loaded.scene, eyeHeight, 0.5f, request.scene, request.options.quiet);
    std::printf("%s\n", proposal.reason.c_str());
    loaded.scene.walkableArea.min = {proposal.area.x, proposal.area.y};
    loaded.scene.walkableArea.max = {proposal.area.z, proposal.area.w};
    loaded.scene.walkableArea.floorHeight = proposal.floorZ;
    loaded.scene.walkableArea.eyeHeight = eyeHeight;
  }
  const CapturePlan plan = planCapture(loaded.scene, request.options);
  std::printf("scene %s: %zu triangles; %d paths x %d samples over [%.2f, %.2f] x [%.2f, %.2f] m at z = %.2f m, "
              "%d probes, %dx%d\n",
              loaded.name.c_str(), loaded.scene.triangleCount(), plan.paths, plan.perPath, plan.area.x, plan.area.z,
              plan.area.y, plan.area.w, plan.eyeZ, request.options.probes, request.options.width,
              request.options.width / 2);
  const CaptureSummary summary = captureDataset(loaded.scene, loaded.name, request.options, request.out);
  std::printf("captured %d samples and %d probes into %s in %.1f s (%.2f panoramas/s) with %s\n", summary.samples,
              summary.probes, request.out.c_str(), summary.seconds,
              double(summary.samples + summary.probes) / std::max(summary.seconds, 1e-9), context->description().c_str());
  return summary;
}

}  // namespace triwalk
