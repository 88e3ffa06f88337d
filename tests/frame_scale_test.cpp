#include "render/walkthrough/frame_scale.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace triwalk {

namespace {

// A machine whose warp takes fixedMs + pixelMs * s^2 at scale s, times a
// deterministic jitter of +-jitter (frame times on llvmpipe vary by 10-20%).
struct SimulatedMachine {
  double fixedMs, pixelMs, jitter = 0.0;
  uint32_t state = 12345u;

  double frame(float scale) {
    state = state * 1664525u + 1013904223u;
    const double unit = double(state >> 8) / double(1u << 24);  // [0, 1)
    return (fixedMs + pixelMs * double(scale) * double(scale)) * (1.0 + jitter * (2.0 * unit - 1.0));
  }
  double exact(float scale) const { return fixedMs + pixelMs * double(scale) * double(scale); }
};

float walk(FrameScaleController& controller, SimulatedMachine& machine, int frames, int* changes = nullptr) {
  float scale = controller.movingScale(1.0f);
  for (int i = 0; i < frames; ++i) {
    controller.record(scale, machine.frame(scale));
    const float next = controller.movingScale(1.0f);
    if (changes && next != scale) ++*changes;
    scale = next;
  }
  return scale;
}

}  // namespace

TEST_CASE("walking frames settle on the largest scale that fits the budget, whatever the machine's fixed and per-pixel costs") {
  const double budget = 33.0;
  const float step = FrameScaleController::kScaleStep;
  // The first two have a fixed part that is most of a small frame, as
  // the setup of the triangles in view is on llvmpipe (docs/history/BENCHMARKS-2026-11.md):
  // there a scale's time predicted from another's alone is too high above
  // it, and only trying the step up finds that it fits.
  for (const SimulatedMachine shape : {SimulatedMachine{20.0, 80.0}, SimulatedMachine{19.0, 122.0},
                                       SimulatedMachine{5.0, 150.0}, SimulatedMachine{0.0, 60.0}}) {
    FrameScaleController controller(budget, 0.25f);
    // Both from above (the first frames, at full resolution) and from below
    // (after a slow stretch that took the walk to its minimum).
    SimulatedMachine machine = shape;
    float scale = walk(controller, machine, 300);
    CHECK(machine.exact(scale) <= budget);
    CHECK(machine.exact(scale + step) > budget);
    SimulatedMachine slow{40.0, 100.0};
    REQUIRE(walk(controller, slow, 60) == doctest::Approx(0.25f));
    scale = walk(controller, machine, 300);
    INFO("fixed " << shape.fixedMs << " ms, per full frame " << shape.pixelMs << " ms: scale " << scale
                  << " after a slow stretch");
    CHECK(machine.exact(scale) <= budget);
    CHECK(machine.exact(scale + step) > budget);
  }
}

TEST_CASE("a step up that did not fit is tried again less and less often") {
  // At 0.40 this machine takes 32.2 ms, at 0.45 35.7 ms: every trial fails.
  FrameScaleController controller(33.0, 0.25f);
  SimulatedMachine machine{19.0, 82.5};
  walk(controller, machine, 60);
  std::vector<int> trials;  // the frames at which the scale went up
  float scale = controller.movingScale(1.0f);
  for (int frame = 0; frame < 1200; ++frame) {
    controller.record(scale, machine.frame(scale));
    const float next = controller.movingScale(1.0f);
    if (next > scale) trials.push_back(frame);
    CHECK(next >= 0.40f - 1e-6f);
    scale = next;
  }
  CHECK(scale == doctest::Approx(0.40f));
  REQUIRE(trials.size() >= 3);
  for (size_t k = 2; k < trials.size(); ++k) {
    INFO("trials at frames " << trials[k - 2] << ", " << trials[k - 1] << ", " << trials[k]);
    CHECK(trials[k] - trials[k - 1] >= trials[k - 1] - trials[k - 2]);
  }
  CHECK(trials.back() - trials[trials.size() - 2] >= FrameScaleController::kLongestWaitBeforeProbe);
}

TEST_CASE("the walking scale does not flicker between sizes on noisy frame times") {
  FrameScaleController controller(33.0, 0.25f);
  SimulatedMachine machine{20.0, 80.0, 0.15};
  walk(controller, machine, 40);
  int changes = 0;
  const float scale = walk(controller, machine, 300, &changes);
  INFO("scale " << scale << ", " << changes << " changes in 300 frames");
  CHECK(changes <= 10);
  CHECK(machine.exact(scale) <= 33.0 * 1.15);
}

TEST_CASE("frames drawn while a reference loads count only when they are over the budget") {
  SUBCASE("a walk that starts before its working set is loaded leaves full resolution on the first slow frame") {
    FrameScaleController controller(33.0, 0.25f);
    // One layer of three at full resolution on llvmpipe (the viewer's bench).
    controller.record(1.0f, 160.0, false);
    CHECK(controller.movingScale(1.0f) <= 0.5f);
  }
  SUBCASE("fast frames with fewer layers do not raise the scale") {
    FrameScaleController controller(33.0, 0.25f);
    SimulatedMachine machine{20.0, 80.0};
    const float settled = walk(controller, machine, 300);
    REQUIRE(settled < 0.8f);
    for (int i = 0; i < 300; ++i) {
      controller.record(controller.movingScale(1.0f), 0.3 * machine.exact(controller.movingScale(1.0f)), false);
    }
    CHECK(controller.movingScale(1.0f) == doctest::Approx(settled));
  }
}

TEST_CASE("the walking scale stays within the minimum, the user's render scale and full resolution") {
  SUBCASE("a budget the machine cannot meet gives the minimum, not less") {
    FrameScaleController controller(33.0, 0.25f);
    SimulatedMachine machine{40.0, 100.0};
    CHECK(walk(controller, machine, 40) == doctest::Approx(0.25f));
  }
  SUBCASE("a fast machine walks at full resolution") {
    FrameScaleController controller(33.0, 0.25f);
    SimulatedMachine machine{2.0, 10.0};
    CHECK(walk(controller, machine, 40) == doctest::Approx(1.0f));
  }
  SUBCASE("after a slow stretch the scale comes back up to full") {
    FrameScaleController controller(33.0, 0.25f);
    SimulatedMachine slow{20.0, 200.0};
    CHECK(walk(controller, slow, 40) < 0.5f);
    SimulatedMachine fast{2.0, 10.0};
    CHECK(walk(controller, fast, 60) == doctest::Approx(1.0f));
  }
  SUBCASE("never above the user's render scale, and full before any frame is measured") {
    FrameScaleController controller(33.0, 0.25f);
    CHECK(controller.movingScale(1.0f) == 1.0f);
    CHECK(controller.movingScale(0.5f) == 0.5f);
  }
}

}  // namespace triwalk
