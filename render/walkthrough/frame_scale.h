#pragma once
// Dynamic resolution for walking on a slow rasterizer (llvmpipe): while the
// camera moves, the warp renders a share of the window's pixels chosen so
// that a frame fits a time budget; once the camera stops, the viewer draws
// one frame at full resolution and keeps it on screen until something
// changes (app/viewer/viewer_app.cpp).
//
// The warp's time is a fixed part (vertex work, per-draw overhead) plus a
// part proportional to the pixels: t = a + b s^2 for the linear scale s.
// The controller keeps a running mean of t / s^2, the cost of a full frame
// as if all of it scaled, and picks s = sqrt(budget / that). Its fixed point
// is a + b s^2 = budget exactly, whatever a and b are, so nothing is tuned
// to one machine. Scales are whole steps of kScaleStep with hysteresis
// upwards, so that the warper's textures (reallocated on every size
// change) do not flip between two sizes.

namespace triwalk {

// The viewer's defaults: 30 frames a second, and never below a quarter of
// each side (below it a walk shows blocks, not a scene).
inline constexpr double kWalkFrameBudgetMilliseconds = 33.0;
inline constexpr float kMinimumWalkingScale = 0.25f;

class FrameScaleController {
public:
  static constexpr float kScaleStep = 0.05f;

  // minimumScale: never below this share of each side (a budget the
  // machine cannot meet gives this scale, not a blur).
  FrameScaleController(double budgetMilliseconds, float minimumScale);

  // The scale for the next frame while the camera moves, at most maximum
  // (the user's render scale). Before any frame is measured: maximum.
  float movingScale(float maximum) const;
  // A frame drawn at scale took milliseconds (the warp, finished).
  void record(float scale, double milliseconds);

  void setBudgetMilliseconds(double milliseconds);

private:
  double budget_;
  float minimum_;
  double fullFrameMilliseconds_ = 0.0;  // running mean of t / s^2; 0 before the first frame
  float scale_ = 1.0f;                  // the current step
};

}  // namespace triwalk
