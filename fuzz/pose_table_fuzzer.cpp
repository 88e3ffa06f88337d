// Fuzzes the pose files of imported captures: the same bytes as a CSV and
// a JSON pose table (readPoseTable) and as a 4x4 matrix file
// (readNumberFile, as extrinsics.txt is read).

#include "core/import/pose_table.h"
#include "core/support/errors.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace triwalk;
  for (const char* name : {"poses.csv", "poses.json"}) {
    const std::filesystem::path path = fuzz::writeInput(name, data, size);
    try {
      (void)readPoseTable(path, PoseMatrix::WorldToCamera, UpAxis::PlusY);
    } catch (const InputError&) {
    }
  }
  const std::filesystem::path matrix = fuzz::writeInput("extrinsics.txt", data, size);
  try {
    (void)poseFromMatrix(matrixFromRows(readNumberFile(matrix, 16)), PoseMatrix::CameraToWorld, matrix.string());
  } catch (const InputError&) {
  }
  return 0;
}
