#pragma once
// Options shared by decimate and eval: the resolution triangle errors are
// computed at, plus the warp, blend and error options.

#include "app/quality_options.h"
#include "core/triangle_error.h"

#include <CLI/CLI.hpp>

namespace triwalk {

struct ErrorArguments {
  int width = 256;
  std::string destinations = "centroid";
  QualityArguments quality;
};

void addErrorOptions(CLI::App& command, ErrorArguments& arguments);
TriangleErrorSettings triangleErrorSettings(const ErrorArguments& arguments);
std::string describeErrorSettings(const TriangleErrorSettings& settings);

}  // namespace triwalk
