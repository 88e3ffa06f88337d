#pragma once
// Camera paths for headless rendering: a file with one pose a line,
//   x y z yaw pitch        (metres, degrees; '#' starts a comment)
// or the presets of the paper's figures: rotating at a point (Fig. 7) and
// translating along a line (Fig. 8).

#include <glm/glm.hpp>

#include <filesystem>
#include <vector>

namespace triwalk {

struct CameraPose {
  glm::vec3 position{0.0f};
  float yawDegrees = 0.0f;
  float pitchDegrees = 0.0f;
};

// Throws InputError naming the file and line.
std::vector<CameraPose> readCameraPath(const std::filesystem::path& path);
void writeCameraPath(const std::filesystem::path& path, const std::vector<CameraPose>& poses);

// A full turn at a point, frames evenly spaced from yaw 0.
std::vector<CameraPose> rotatePath(glm::vec3 at, int frames, float pitchDegrees = 0.0f);
// From one point to another (inclusive), looking at a fixed yaw.
std::vector<CameraPose> translatePath(glm::vec3 from, glm::vec3 to, int frames, float yawDegrees, float pitchDegrees = 0.0f);

}  // namespace triwalk
