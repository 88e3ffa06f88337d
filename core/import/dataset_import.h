#pragma once
// A capture in one of the layouts (capture_layout.h) to a triwalk data
// set: checked whole before any image is decoded, then converted view by
// view (sRGB colour to linear half, depth to metres along the ray with
// invalid pixels as +inf, photo columns to triwalk's, tilted cameras
// resampled upright), a seeded random fraction held out as probes, written
// beside the destination and moved into place only when complete.

#include "core/import/capture_layout.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace triwalk {

struct CaptureImportOptions {
  DepthKind depthKind = DepthKind::Euclidean;
  UpAxis up = UpAxis::PlusZ;
  double metresPerUnit = 1.0;    // of the poses' positions
  double probesFraction = 0.1;   // of the views, held out as probes
  unsigned seed = 1;             // of the probes' choice
  bool quiet = false;
};

struct CaptureImportReport {
  int samples = 0;
  int probes = 0;
  int width = 0;
  int height = 0;
  size_t invalidDepthPixels = 0;  // 0, +inf or masked: no surface (+inf) in the data set
  size_t pixels = 0;
  std::string mostInvalidView;    // the view with the largest share of them
  double mostInvalidFraction = 0.0;
  int resampledViews = 0;         // tilted beyond negligibleTiltRadians
  double largestTiltDegrees = 0.0;
  double seconds = 0.0;
};

// Throws InputError naming the file for an unreadable image, a size
// mismatch (colour, depth, mask, between views, width != 2 x height), a
// non-finite pose or two views at one position (within 1 mm in x, y).
CaptureImportReport importCapture(const std::vector<SourceView>& views, const CaptureImportOptions& options,
                                  const std::string& sceneName, const nlohmann::json& provenance,
                                  const std::filesystem::path& out);

}  // namespace triwalk
