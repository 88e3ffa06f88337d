#include "core/image/half_float.h"

#include "core/support/errors.h"

#include <Imath/half.h>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <immintrin.h>
#define TRIWALK_F16C_PATH 1
#endif

namespace triwalk {

namespace {

void portableHalvesToFloats(const uint16_t* halves, float* floats, size_t count) {
  for (size_t i = 0; i < count; ++i) floats[i] = imath_half_to_float(halves[i]);
}

void portableFloatsToHalves(const float* floats, uint16_t* halves, size_t count) {
  for (size_t i = 0; i < count; ++i) halves[i] = imath_float_to_half(floats[i]);
}

#if defined(TRIWALK_F16C_PATH)
// Compiled for F16C (and the AVX it needs) alone; called only where the
// processor has both.
constexpr int kNearestEven = _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC;

__attribute__((target("avx,f16c"))) void hardwareHalvesToFloats(const uint16_t* halves, float* floats, size_t count) {
  size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    const __m128i eight = _mm_loadu_si128(reinterpret_cast<const __m128i*>(halves + i));
    _mm256_storeu_ps(floats + i, _mm256_cvtph_ps(eight));
  }
  for (; i < count; ++i) floats[i] = _cvtsh_ss(halves[i]);
}

__attribute__((target("avx,f16c"))) void hardwareFloatsToHalves(const float* floats, uint16_t* halves, size_t count) {
  size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(halves + i), _mm256_cvtps_ph(_mm256_loadu_ps(floats + i), kNearestEven));
  }
  for (; i < count; ++i) halves[i] = _cvtss_sh(floats[i], kNearestEven);
}
#endif

// Whether to convert by F16C; asking for it where there is none is a bug.
bool useHardware(HalfConversion conversion) {
  if (conversion == HalfConversion::Portable) return false;
  const bool available = hardwareHalfConversion();
  TRIWALK_CHECK(available || conversion == HalfConversion::Best, "this processor has no F16C half conversion");
  return available;
}

}  // namespace

bool hardwareHalfConversion() {
#if defined(TRIWALK_F16C_PATH)
  // CPUID's F16C and AVX bits, and the system saving the AVX registers
  // (OSXSAVE, then XCR0's SSE and AVX state bits); Clang's
  // __builtin_cpu_supports knows no "f16c".
  static const bool available = [] {
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx)) return false;
    if (!(ecx & bit_F16C) || !(ecx & bit_AVX) || !(ecx & bit_OSXSAVE)) return false;
    uint32_t low = 0, high = 0;
    __asm__("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
    return (low & 0x6) == 0x6;
  }();
  return available;
#else
  return false;
#endif
}

void halvesToFloats(std::span<const uint16_t> halves, std::span<float> floats, HalfConversion conversion) {
  TRIWALK_CHECK(halves.size() == floats.size(), "one float per half");
  if (useHardware(conversion)) {
#if defined(TRIWALK_F16C_PATH)
    hardwareHalvesToFloats(halves.data(), floats.data(), halves.size());
    return;
#endif
  }
  portableHalvesToFloats(halves.data(), floats.data(), halves.size());
}

void floatsToHalves(std::span<const float> floats, std::span<uint16_t> halves, HalfConversion conversion) {
  TRIWALK_CHECK(halves.size() == floats.size(), "one half per float");
  if (useHardware(conversion)) {
#if defined(TRIWALK_F16C_PATH)
    hardwareFloatsToHalves(floats.data(), halves.data(), floats.size());
    return;
#endif
  }
  portableFloatsToHalves(floats.data(), halves.data(), floats.size());
}

}  // namespace triwalk
