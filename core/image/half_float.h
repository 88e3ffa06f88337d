#pragma once
// Arrays converted between float and half float (IEEE binary16, as
// OpenEXR stores them): with the F16C instructions where the processor
// has them, else Imath's conversions. The build targets the baseline
// x86-64, which has no F16C, so the choice is made once at run time.
// Both give the same floats: half to float is exact, and float to half
// rounds to the nearest even either way; only the payload bits of a NaN
// may differ. So results never depend on the processor. The warped-layer
// cache converts every pixel of every cached layer, and reading them with
// Imath's 256 KiB table was the largest share of a decimation's blend
// (docs/history/BENCHMARKS-2026-11.md).

#include <cstdint>
#include <span>

namespace triwalk {

enum class HalfConversion {
  Best,      // Hardware where the processor has it, else Portable
  Portable,  // Imath's
  Hardware,  // F16C; only where hardwareHalfConversion() says so
};

// Whether this processor converts halves in hardware (x86-64 with F16C).
bool hardwareHalfConversion();

// halves.size() == floats.size().
void halvesToFloats(std::span<const uint16_t> halves, std::span<float> floats,
                    HalfConversion conversion = HalfConversion::Best);
void floatsToHalves(std::span<const float> floats, std::span<uint16_t> halves,
                    HalfConversion conversion = HalfConversion::Best);

}  // namespace triwalk
