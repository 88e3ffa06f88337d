// Fuzzes readPanoramaExr: any bytes as an OpenEXR file.

#include "core/io/exr_io.h"
#include "core/support/errors.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace triwalk;
  const std::filesystem::path path = fuzz::writeInput("view.exr", data, size);
  try {
    (void)readPanoramaExr(path);
  } catch (const InputError&) {
  }
  return 0;
}
