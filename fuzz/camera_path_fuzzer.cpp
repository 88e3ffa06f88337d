// Fuzzes readCameraPath: any bytes as a camera path file.

#include "core/io/camera_path.h"
#include "core/support/errors.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace triwalk;
  const std::filesystem::path path = fuzz::writeInput("path.txt", data, size);
  try {
    (void)readCameraPath(path);
  } catch (const InputError&) {
  }
  return 0;
}
