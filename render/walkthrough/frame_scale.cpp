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
  if (milliseconds != budget_) forgetCeiling();  // a step that did not fit may fit the new budget
  budget_ = milliseconds;
}

float FrameScaleController::movingScale(float maximum) const { return std::min(scale_, maximum); }

void FrameScaleController::moveTo(float scale, bool upwards) {
  scale_ = scale;
  enteredUpwards_ = upwards;
  fullFrameMilliseconds_ = 0.0;
  framesAtScale_ = 0;
}

bool FrameScaleController::reachesCeiling(float scale) const {
  return scale > ceiling_ - 0.5f * kScaleStep;
}

void FrameScaleController::forgetCeiling() {
  ceiling_ = kNoCeiling;
  waitAtCeiling_ = kFramesBeforeProbe;
}

void FrameScaleController::record(float scale, double milliseconds, bool complete) {
  if (!(scale > 0.0f) || !std::isfinite(milliseconds) || milliseconds <= 0.0) return;
  if (!complete && milliseconds <= budget_) return;
  const double fullFrame = milliseconds / (double(scale) * double(scale));
  fullFrameMilliseconds_ = fullFrameMilliseconds_ > 0.0
                               ? (1.0 - kNewestWeight) * fullFrameMilliseconds_ + kNewestWeight * fullFrame
                               : fullFrame;
  ++framesAtScale_;
  const auto step = [&](double value) {
    return std::clamp(float(std::floor(value / kScaleStep + 1e-6)) * kScaleStep, minimum_, 1.0f);
  };
  const double wanted = std::sqrt(budget_ / fullFrameMilliseconds_);
  // A frame drawn below the current step (the user's render scale caps it)
  // measures a scale the controller is not at: it cannot try a step up.
  const bool atStep = std::abs(scale - scale_) < 0.5f * kScaleStep;

  if (step(wanted) < scale_) {
    // Over budget. A step up on trial is judged on a few frames, not one,
    // unless the first is far over (a slow stretch, not noise).
    if (probing_ && atStep && framesAtScale_ < kFramesToJudgeProbe && milliseconds < 1.25 * budget_) return;
    // A step entered upwards that does not fit (a failed trial, or a kept
    // one that noise took over budget) is the ceiling: trying it again
    // waits twice as long, so that a budget between two steps does not flip
    // the size every few frames. Steps below it are tried at once.
    if (enteredUpwards_) {
      ceiling_ = scale_;
      waitAtCeiling_ = std::min(2 * waitAtCeiling_, kLongestWaitBeforeProbe);
    }
    // Down at once to the step below the wanted scale (a frame over budget
    // is what this is for); with a fixed part the prediction is too low, so
    // the next frames may step down again. A failed trial goes back one.
    moveTo(probing_ ? std::max(step(scale_ - 0.5 * kScaleStep), step(wanted)) : step(wanted), false);
    probing_ = false;
    return;
  }
  if (probing_) {
    // The step up on trial fits once its frames are enough to judge.
    if (framesAtScale_ >= kFramesToJudgeProbe) {
      probing_ = false;
      if (reachesCeiling(scale_)) ceiling_ = kNoCeiling;
    }
    return;
  }
  // Up without a trial when even the prediction, pessimistic above the
  // current scale, says the step is half a step clear of fitting.
  const float predicted = step(wanted - 0.5 * kScaleStep);
  if (predicted > scale_) {
    if (reachesCeiling(predicted)) forgetCeiling();
    moveTo(predicted, true);
    return;
  }
  const float up = step(scale_ + 1.5 * kScaleStep);
  const int wait = reachesCeiling(up) ? waitAtCeiling_ : kFramesBeforeProbe;
  if (atStep && up > scale_ && framesAtScale_ >= wait) {
    moveTo(up, true);
    probing_ = true;
  }
}

}  // namespace triwalk
