// Fuzzes the numbers of a data set and of decimate's and eval's options,
// driven through the selection and the evaluation (fuzz/numeric_drive.h).

#include "fuzz/fuzz_input.h"
#include "fuzz/numeric_drive.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  triwalk::fuzz::driveNumbers(data, size, TRIWALK_FUZZ_DATASET, triwalk::fuzz::scratchDirectory());
  return 0;
}
