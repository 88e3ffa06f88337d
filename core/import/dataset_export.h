#pragma once
// A triwalk data set written in one of the capture layouts
// (capture_layout.h): samples and probes alike become views named after
// their files (s0000, p0000, ...), so a data set can be handed to other
// tools, or imported back (the round trip the tests check).

#include "core/import/capture_layout.h"
#include "core/io/dataset.h"

#include <filesystem>

namespace triwalk {

// Writes beside out and moves into place when complete; refuses an out
// that exists and is not empty. Returns the number of views written.
int exportDataset(const Dataset& dataset, CaptureLayout layout, const std::filesystem::path& out, bool quiet);

}  // namespace triwalk
