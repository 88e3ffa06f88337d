#pragma once
// The numeric harness's one run, shared by the fuzzer (numeric_fuzzer.cpp)
// and the test that replays its corpus (tests/fuzz_regression_test.cpp).
//
// The bytes choose numbers from the values that break arithmetic (NaN,
// infinities, denormals, signed zeros, magnitudes from 1e-30 to 1e308) or
// take any double, and put them where a user can: the positions and yaws
// of a tiny data set's views in its manifest, and the options of decimate
// and eval (blend interval, r_min, error weights and tolerance, warp
// thresholds, relative and absolute error thresholds, target count,
// refinement radius). A value the command line refuses is refused here by
// the same ranges (core's OptionRange constants); the rest is driven
// through what the two commands compute: open the data set, select
// references (collapses and refinement), write and read the selection,
// evaluate it and the baselines on the probes.
//
// A finding: a crash, a sanitizer report, an exception other than
// InputError, or a mean error that is not a finite number.

#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace triwalk::fuzz {

// Runs the bytes against a copy of the data set in `seedDataset`, made
// once in `scratch`. Returns true when the inputs were accepted and
// driven through, false when a reader or an option check refused them.
bool driveNumbers(const uint8_t* data, size_t size, const std::filesystem::path& seedDataset,
                  const std::filesystem::path& scratch);

}  // namespace triwalk::fuzz
