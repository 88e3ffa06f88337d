#pragma once
// Dynamic resolution for walking on a slow rasterizer (llvmpipe): while the
// camera moves, the warp renders a share of the window's pixels chosen so
// that a frame fits a time budget; once the camera stops, the viewer draws
// one frame at full resolution and keeps it on screen until something
// changes (app/viewer/viewer_app.cpp).
//
// The warp's time is a fixed part (the setup of the triangles in view) plus a
// part proportional to the pixels: t = a + b s^2 for the linear scale s.
// The controller keeps a running mean of t / s^2 at the current scale, the
// cost of a full frame as if all of it scaled, and predicts another scale's
// time from it. That prediction is exact without a fixed part, too high
// above the current scale and too low below it: a step down that it calls
// enough may not be (the next frames step down again), and a step up that
// it calls too slow may fit. On llvmpipe the fixed part is most of a small
// frame (BENCHMARKS.md), so the prediction alone would keep the walk at the
// scale of its slowest stretch. So while frames fit, the controller tries
// the next step up now and then and keeps it if its frames fit too. A step
// reached upwards that then does not fit (a failed trial, or a kept one
// that noise took over budget) becomes the ceiling: it is tried again only
// after twice as long as last time, which bounds how often the size
// changes when the budget falls between two steps, while the steps below
// it are tried at once (after a slow stretch the walk climbs back within a
// few seconds). Nothing is fitted to one machine: the trials measure the
// step they try.
//
// Scales are whole steps of kScaleStep, so that the warper's textures
// (reallocated on every size change) do not flip between many sizes.

namespace triwalk {

// The viewer's defaults: 30 frames a second, and never below a quarter of
// each side (below it a walk shows blocks, not a scene).
inline constexpr double kWalkFrameBudgetMilliseconds = 33.0;
inline constexpr float kMinimumWalkingScale = 0.25f;

class FrameScaleController {
public:
  static constexpr float kScaleStep = 0.05f;
  // Frames that fit at one scale before the next step up is tried, and the
  // longest wait before the ceiling is tried again (at 30 frames a second:
  // one and eight seconds).
  static constexpr int kFramesBeforeProbe = 30;
  static constexpr int kLongestWaitBeforeProbe = 240;
  // Frames a step up on trial is judged on (its running mean), unless one
  // is far over the budget.
  static constexpr int kFramesToJudgeProbe = 6;

  // minimumScale: never below this share of each side (a budget the
  // machine cannot meet gives this scale, not a blur).
  FrameScaleController(double budgetMilliseconds, float minimumScale);

  // The scale for the next frame while the camera moves, at most maximum
  // (the user's render scale). Before any frame is measured: maximum.
  float movingScale(float maximum) const;
  // A frame drawn at scale took milliseconds (the warp, finished).
  // complete: it drew every reference. A frame drawn while one is still
  // loading warps fewer layers, so it is no measure of the warp's cost,
  // except that one over the budget would be further over with all of
  // them: only those count. Otherwise a walk that starts before its
  // working set is loaded stays at full resolution until it is.
  void record(float scale, double milliseconds, bool complete = true);

  void setBudgetMilliseconds(double milliseconds);

private:
  static constexpr float kNoCeiling = 2.0f;

  void moveTo(float scale, bool upwards);
  // Whether a step is the ceiling or above it (steps compared to half a step).
  bool reachesCeiling(float scale) const;
  void forgetCeiling();

  double budget_;
  float minimum_;
  float scale_ = 1.0f;                      // the current step
  bool enteredUpwards_ = false;             // the current step was reached by going up
  bool probing_ = false;                    // the current step is a step up on trial
  double fullFrameMilliseconds_ = 0.0;      // running mean of t / s^2 at the current step; 0 before its first frame
  int framesAtScale_ = 0;                   // frames recorded at the current step
  float ceiling_ = kNoCeiling;              // the lowest step entered upwards that then did not fit
  int waitAtCeiling_ = kFramesBeforeProbe;  // frames that fit before the ceiling is tried again
};

}  // namespace triwalk
