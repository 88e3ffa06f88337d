#pragma once
// Four lanes of float and their masks (all bits set where true), as GCC's
// and Clang's vector extensions give them: SSE2 on the baseline x86-64,
// plain loops elsewhere. The code written with them does, lane by lane,
// what a scalar function does, so it gives the same bits (the project
// compiles without contraction into fused multiply-adds).

#include <bit>
#include <cstdint>
#include <cstring>

namespace triwalk {

using Floats4 = float __attribute__((vector_size(16)));
using Masks4 = int32_t __attribute__((vector_size(16)));

inline Floats4 splat(float value) { return Floats4{value, value, value, value}; }

// std::fabs lane by lane: the sign bit cleared.
inline Floats4 absolute(Floats4 lanes) { return std::bit_cast<Floats4>(std::bit_cast<Masks4>(lanes) & 0x7fffffff); }

// Four consecutive floats, at any alignment.
inline Floats4 loadFloats4(const float* values) {
  Floats4 lanes;
  std::memcpy(&lanes, values, sizeof lanes);
  return lanes;
}

inline void storeFloats4(Floats4 lanes, float* values) { std::memcpy(values, &lanes, sizeof lanes); }

}  // namespace triwalk
