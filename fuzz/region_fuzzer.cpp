// Fuzzes the walkable-region reader: a JSON file whose content is the
// manifest's "walkable" object; a region that validates is also sampled
// (containment of points, segments and triangles, area, area weights),
// as decimate does.

#include "core/geometry/walkable_region.h"
#include "core/io/json_fields.h"
#include "core/support/errors.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace triwalk;
  const std::filesystem::path path = fuzz::writeInput("region.json", data, size);
  try {
    const WalkableRegion region = WalkableRegion::fromJson(readJsonFile(path), path.string());
    glm::dvec2 low, high;
    region.bounds(low, high);
    (void)region.area();
    (void)region.contains((low + high) * 0.5);
    (void)region.containsSegment(low, high);
    (void)region.containsTriangle(low, high, {low.x, high.y});
    const std::vector<glm::dvec2> samples = {low, high, {low.x, high.y}};
    (void)sampleAreaWeights(samples, region);
  } catch (const InputError&) {
  }
  return 0;
}
