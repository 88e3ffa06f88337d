#include "core/geometry/float_arc_tangent.h"

#include <bit>

namespace triwalk {

namespace {

using namespace arc_tangent_detail;

// atanFloat of finite, non-negative lanes. Each of its cases is computed by
// the same operations: the interval's reduction is one quotient, whose
// numerator and denominator are chosen per lane (x / 1 = x for the lowest
// interval), and the lanes past its ends take its end values.
Floats4 atanOfNonNegative(Floats4 x) {
  const Masks4 magnitude = std::bit_cast<Masks4>(x);
  const Masks4 huge = magnitude >= 0x4c000000, tiny = magnitude < 0x31000000, low = magnitude < 0x3ee00000;
  const Masks4 first = magnitude < 0x3f300000, second = magnitude < 0x3f980000, third = magnitude < 0x401c0000;
  const Floats4 one = splat(1.0f);
  const Floats4 numerator = low      ? x
                            : first  ? 2.0f * x - one
                            : second ? x - one
                            : third  ? x - 1.5f
                                     : splat(-1.0f);
  const Floats4 denominator = low      ? one
                              : first  ? 2.0f + x
                              : second ? x + one
                              : third  ? one + 1.5f * x
                                       : x;
  const Floats4 r = numerator / denominator;
  const Floats4 sum = seriesSum(r);
  const Floats4 high = first ? splat(kHigh[0]) : second ? splat(kHigh[1]) : third ? splat(kHigh[2]) : splat(kHigh[3]);
  const Floats4 lowPart = first ? splat(kLow[0]) : second ? splat(kLow[1]) : third ? splat(kLow[2]) : splat(kLow[3]);
  const Floats4 reduced = low ? r - r * sum : high - ((r * sum - lowPart) - r);
  return huge ? splat(kHigh[3] + kLow[3]) : tiny ? x : reduced;
}

}  // namespace

Floats4 atan2Floats(Floats4 y, Floats4 x, Masks4& unhandled) {
  const Masks4 xBits = std::bit_cast<Masks4>(x), yBits = std::bit_cast<Masks4>(y);
  const Masks4 xMagnitude = xBits & 0x7fffffff, yMagnitude = yBits & 0x7fffffff;
  const Masks4 exponentGap = (yMagnitude - xMagnitude) >> 23;
  unhandled |= (xMagnitude == 0) | (yMagnitude == 0) | (xMagnitude >= 0x7f800000) | (yMagnitude >= 0x7f800000) |
               (xBits == 0x3f800000) | (exponentGap > 60) | (exponentGap < -60);
  const Floats4 z = atanOfNonNegative(absolute(y / x));
  const Masks4 yNegative = yBits < 0, xNegative = xBits < 0;
  return xNegative ? (yNegative ? (z - kPiLow) - kPiHigh : kPiHigh - (z - kPiLow)) : (yNegative ? -z : z);
}

Floats4 hypotFloats(Floats4 x, Floats4 y) {
  Floats4 result;
  for (int lane = 0; lane < 4; ++lane) {
    result[lane] = float(std::sqrt(double(x[lane]) * double(x[lane]) + double(y[lane]) * double(y[lane])));
  }
  return result;
}

}  // namespace triwalk
