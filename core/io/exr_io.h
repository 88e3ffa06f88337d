#pragma once
// OpenEXR I/O of one RGB-D panorama: channels R, G, B (half, linear) and
// Z (float, Euclidean distance in metres, +inf = no surface). OpenEXR's
// exceptions stop here and come out as InputError naming the file.

#include "core/image/image.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>

namespace triwalk {

// The largest panorama triwalk reads (32768 x 16384): a header is checked
// against it, and against the expected size, before any pixel memory is
// allocated, so a 1 KB file cannot claim gigabytes (found by fuzzing); so
// is every header attribute's size against what the file holds.
inline constexpr int kMaxPanoramaWidth = 32768;

// The values readPanoramaExr accepts: a finite colour; a distance neither
// NaN nor negative (+inf: no surface).
bool acceptedPanoramaColor(glm::vec3 color);
bool acceptedPanoramaDistance(float distance);

// Reads and validates: the size (at most kMaxPanoramaWidth x half, and
// expectedSize if given), all four channels present, finite non-negative
// color, distance neither NaN nor negative.
Panorama readPanoramaExr(const std::filesystem::path& path, std::optional<glm::ivec2> expectedSize = std::nullopt);

// Writes atomically (temporary file + rename).
void writePanoramaExr(const std::filesystem::path& path, const Panorama& panorama);

// The panorama readPanoramaExr returns from the file writePanoramaExr
// writes of this one, without the file: the colours rounded to half floats
// as the file stores them (the distances are stored as they are).
Panorama asWrittenToExr(const Panorama& panorama);

// A single-channel float depth map (the depth EXRs of RGB-D captures): the
// file's only channel, else the first of Z, Y, R, depth. NaN or negative
// values are refused; 0 and +inf come back as they are (the importer
// treats both as "no depth").
ScalarImage readDepthExr(const std::filesystem::path& path);

// The size of an EXR's data window, from its header alone.
glm::ivec2 exrFileSize(const std::filesystem::path& path);

// Writes one float channel "Z", atomically.
void writeDepthExr(const std::filesystem::path& path, const ScalarImage& depth);

}  // namespace triwalk
