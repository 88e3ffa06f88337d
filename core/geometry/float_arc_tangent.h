#pragma once
// Single-precision arc tangents and hypotenuse with fixed arithmetic: the
// operations of fdlibm's atanf and atan2f (the algorithm glibc 2.36 uses;
// Copyright (C) 1993 by Sun Microsystems, Inc. Developed at SunPro, a Sun
// Microsystems, Inc. business. Permission to use, copy, modify, and
// distribute this software is freely granted, provided that this notice
// is preserved) and glibc 2.35's hypotf, written out so that
//   - every panorama image point is the same on any C library (a libm's
//     last bits would otherwise move the greedy selection's path), and
//   - four of them run at once (atan2Floats), lane by lane the same
//     operations as the scalar functions, so the same bits: the CPU warp
//     projects every pixel it colours from a simplified mesh this way.
// On Debian bookworm's glibc (2.36) each function returns the C library's
// bits for every input (checked over every float for atanFloat and over
// 400 million pairs for atan2Float and hypotFloat; tests/projection_test.cpp
// checks the lanes against the scalar functions and both against double
// precision). Compiled without contraction into fused multiply-adds
// (the project's -ffp-contract=off), which would round differently.

#include "core/support/float_lanes.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace triwalk {

namespace arc_tangent_detail {

inline constexpr float kHigh[] = {4.6364760399e-01f, 7.8539812565e-01f, 9.8279368877e-01f, 1.5707962513e+00f};
inline constexpr float kLow[] = {5.0121582440e-09f, 3.7748947079e-08f, 3.4473217170e-08f, 7.5497894159e-08f};
inline constexpr float kOdd[] = {3.3333334327e-01f, 1.4285714924e-01f, 9.0908870101e-02f, 6.6610731184e-02f,
                                 4.9768779427e-02f, 1.6285819933e-02f};
inline constexpr float kEven[] = {-2.0000000298e-01f, -1.1111110449e-01f, -7.6918758452e-02f, -5.8335702866e-02f,
                                  -3.6531571299e-02f};
inline constexpr float kHalfPi = 1.5707963705e+00f;
inline constexpr float kPiHigh = 3.1415927410e+00f;
inline constexpr float kPiLow = -8.7422776573e-08f;
inline constexpr float kQuarterPi = 7.8539818525e-01f;
inline constexpr float kTiny = 1.0e-30f;

// The series' two halves on the reduced argument r: atan(r) ~ r - r (odd + even).
template <typename T>
T seriesSum(T r) {
  const T z = r * r, w = z * z;
  const T odd = z * (kOdd[0] + w * (kOdd[1] + w * (kOdd[2] + w * (kOdd[3] + w * (kOdd[4] + w * kOdd[5])))));
  const T even = w * (kEven[0] + w * (kEven[1] + w * (kEven[2] + w * (kEven[3] + w * kEven[4]))));
  return odd + even;
}

}  // namespace arc_tangent_detail

inline float atanFloat(float x) {
  using namespace arc_tangent_detail;
  const int32_t signedBits = std::bit_cast<int32_t>(x);
  const int32_t magnitude = signedBits & 0x7fffffff;
  if (magnitude >= 0x4c000000) {  // |x| >= 2^25, or NaN
    if (magnitude > 0x7f800000) return x + x;
    return signedBits > 0 ? kHigh[3] + kLow[3] : -kHigh[3] - kLow[3];
  }
  int interval;
  if (magnitude < 0x3ee00000) {              // |x| < 0.4375
    if (magnitude < 0x31000000) return x;  // |x| < 2^-29
    interval = -1;
  } else {
    x = std::fabs(x);
    if (magnitude < 0x3f980000) {    // |x| < 1.1875
      if (magnitude < 0x3f300000) {  // |x| < 0.6875
        interval = 0, x = (2.0f * x - 1.0f) / (2.0f + x);
      } else {
        interval = 1, x = (x - 1.0f) / (x + 1.0f);
      }
    } else if (magnitude < 0x401c0000) {  // |x| < 2.4375
      interval = 2, x = (x - 1.5f) / (1.0f + 1.5f * x);
    } else {
      interval = 3, x = -1.0f / x;
    }
  }
  const float sum = seriesSum(x);
  if (interval < 0) return x - x * sum;
  const float z = kHigh[interval] - ((x * sum - kLow[interval]) - x);
  return signedBits < 0 ? -z : z;
}

inline float atan2Float(float y, float x) {
  using namespace arc_tangent_detail;
  const int32_t xBits = std::bit_cast<int32_t>(x), yBits = std::bit_cast<int32_t>(y);
  const int32_t xMagnitude = xBits & 0x7fffffff, yMagnitude = yBits & 0x7fffffff;
  if (xMagnitude > 0x7f800000 || yMagnitude > 0x7f800000) return x + y;  // NaN
  if (xBits == 0x3f800000) return atanFloat(y);                         // x = 1
  const int quadrant = ((yBits >> 31) & 1) | ((xBits >> 30) & 2);        // 2 sign(x) + sign(y)
  if (yMagnitude == 0) {
    switch (quadrant) {
      case 0:
      case 1: return y;
      case 2: return kPiHigh + kTiny;
      default: return -kPiHigh - kTiny;
    }
  }
  if (xMagnitude == 0) return yBits < 0 ? -kHalfPi - kTiny : kHalfPi + kTiny;
  if (xMagnitude == 0x7f800000) {
    if (yMagnitude == 0x7f800000) {
      switch (quadrant) {
        case 0: return kQuarterPi + kTiny;
        case 1: return -kQuarterPi - kTiny;
        case 2: return 3.0f * kQuarterPi + kTiny;
        default: return -3.0f * kQuarterPi - kTiny;
      }
    }
    switch (quadrant) {
      case 0: return 0.0f;
      case 1: return -0.0f;
      case 2: return kPiHigh + kTiny;
      default: return -kPiHigh - kTiny;
    }
  }
  if (yMagnitude == 0x7f800000) return yBits < 0 ? -kHalfPi - kTiny : kHalfPi + kTiny;
  const int32_t exponentGap = (yMagnitude - xMagnitude) >> 23;
  float z;
  if (exponentGap > 60) {
    z = kHalfPi + 0.5f * kPiLow;
  } else if (xBits < 0 && exponentGap < -60) {
    z = 0.0f;
  } else {
    z = atanFloat(std::fabs(y / x));
  }
  switch (quadrant) {
    case 0: return z;
    case 1: return -z;
    case 2: return kPiHigh - (z - kPiLow);
    default: return (z - kPiLow) - kPiHigh;
  }
}

// sqrt(x^2 + y^2), the squares summed in double (each exact) and rounded once.
inline float hypotFloat(float x, float y) {
  if (!std::isfinite(x) || !std::isfinite(y)) {
    if (std::isinf(x) || std::isinf(y)) return std::numeric_limits<float>::infinity();
    return x + y;
  }
  return float(std::sqrt(double(x) * double(x) + double(y) * double(y)));
}

// atan2Float lane by lane, for the lanes it leaves out of `unhandled`: it
// sets the lanes whose inputs take one of atan2Float's special cases (a
// zero, an infinity, a NaN, x = 1, operands 2^60 apart), whose results
// here mean nothing and which the caller computes with atan2Float.
Floats4 atan2Floats(Floats4 y, Floats4 x, Masks4& unhandled);

// hypotFloat lane by lane, for finite lanes.
Floats4 hypotFloats(Floats4 x, Floats4 y);

}  // namespace triwalk
