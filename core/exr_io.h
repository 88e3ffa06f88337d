#pragma once
// OpenEXR I/O of one RGB-D panorama: channels R, G, B (half, linear) and
// Z (float, Euclidean distance in metres, +inf = no surface). OpenEXR's
// exceptions stop here and come out as InputError naming the file.

#include "core/image.h"

#include <filesystem>

namespace triwalk {

// Reads and validates: all four channels present, finite non-negative
// color, distance neither NaN nor negative.
Panorama readPanoramaExr(const std::filesystem::path& path);

// Writes atomically (temporary file + rename).
void writePanoramaExr(const std::filesystem::path& path, const Panorama& panorama);

}  // namespace triwalk
