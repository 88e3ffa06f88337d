#include "render/walkthrough/frame_scale.h"

#include "core/support/errors.h"

#include <algorithm>
#include <cmath>

namespace triwalk {

namespace {

// Weight of the newest frame in the running mean: frame times on llvmpipe
// vary by 10-20% from frame to frame, so one slow frame moves the scale by
// a third of what it would alone.
constexpr double kNewestWeight = 0.3;

}  // namespace

FrameScaleController::FrameScaleController(double budgetMilliseconds, float minimumScale)
    : budget_(budgetMilliseconds), minimum_(minimumScale) {
  TRIWALK_CHECK(budgetMilliseconds > 0.0 && minimumScale > 0.0f && minimumScale <= 1.0f,
                "frame budget and minimum scale must be positive");
}

void FrameScaleController::setBudgetMilliseconds(double milliseconds) {
  TRIWALK_CHECK(milliseconds > 0.0, "frame budget must be positive");
  budget_ = milliseconds;
}

float FrameScaleController::movingScale(float maximum) const { return std::min(scale_, maximum); }

void FrameScaleController::record(float scale, double milliseconds) {
  if (!(scale > 0.0f) || !std::isfinite(milliseconds) || milliseconds <= 0.0) return;
  const double fullFrame = milliseconds / (double(scale) * double(scale));
  fullFrameMilliseconds_ = fullFrameMilliseconds_ > 0.0
                               ? (1.0 - kNewestWeight) * fullFrameMilliseconds_ + kNewestWeight * fullFrame
                               : fullFrame;
  const double wanted = std::sqrt(budget_ / fullFrameMilliseconds_);
  // Whole steps: down at once to the step below the wanted scale (a frame
  // over budget is what this is for); up only when the wanted scale is half
  // a step clear of the next one, so that noise near a step's edge does not
  // flip between two sizes.
  const auto step = [&](double value) {
    return std::clamp(float(std::floor(value / kScaleStep + 1e-6)) * kScaleStep, minimum_, 1.0f);
  };
  if (step(wanted) < scale_) {
    scale_ = step(wanted);
  } else if (step(wanted - 0.5 * kScaleStep) > scale_) {
    scale_ = step(wanted - 0.5 * kScaleStep);
  }
}

}  // namespace triwalk
