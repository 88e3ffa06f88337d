#include "core/selection/collapse/collapse_log.h"

#include "core/support/errors.h"

#include <algorithm>

namespace triwalk {

const char* placementName(PlacementKind kind) {
  switch (kind) {
    case PlacementKind::First:
      return "first";
    case PlacementKind::Second:
      return "second";
    case PlacementKind::Midpoint:
      return "midpoint";
    case PlacementKind::OneRing:
      return "one-ring";
    case PlacementKind::Relocation:
      return "relocation";
    case PlacementKind::Removal:
      return "removal";
  }
  return "?";
}

namespace {

std::vector<Triangle> replace(std::vector<Triangle> triangles, const std::vector<Triangle>& remove,
                              const std::vector<Triangle>& add) {
  for (const Triangle& t : remove) {
    const auto it = std::find(triangles.begin(), triangles.end(), t);
    TRIWALK_CHECK(it != triangles.end(), "collapse log does not match the mesh");
    triangles.erase(it);
  }
  triangles.insert(triangles.end(), add.begin(), add.end());
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

}  // namespace

std::vector<Triangle> replayForward(std::vector<Triangle> initial, std::span<const Collapse> log, size_t steps) {
  for (size_t i = 0; i < std::min(steps, log.size()); ++i)
    initial = replace(std::move(initial), log[i].removed, log[i].added);
  return initial;
}

std::vector<Triangle> replayBackward(std::vector<Triangle> final, std::span<const Collapse> log, size_t steps) {
  for (size_t i = 0; i < std::min(steps, log.size()); ++i) {
    const Collapse& collapse = log[log.size() - 1 - i];
    final = replace(std::move(final), collapse.added, collapse.removed);
  }
  return final;
}

int samplesAfter(int initialSamples, std::span<const Collapse> log, size_t steps) {
  const auto end = log.begin() + ptrdiff_t(std::min(steps, log.size()));
  return initialSamples -
         int(std::count_if(log.begin(), end, [](const Collapse& c) { return c.kind != PlacementKind::Relocation; }));
}

std::optional<size_t> lastStepWithSamples(int initialSamples, std::span<const Collapse> log, int samples) {
  std::optional<size_t> last;
  int count = initialSamples;
  for (size_t step = 0; step <= log.size(); ++step) {
    if (step > 0 && log[step - 1].kind != PlacementKind::Relocation) --count;
    if (count == samples) last = step;
  }
  return last;
}

}  // namespace triwalk
