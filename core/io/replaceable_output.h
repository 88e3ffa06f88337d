#pragma once
// An output file a command may replace: one that does not exist yet, is
// empty, or holds an output of the same kind. Anything else (a data set's
// manifest, another command's table, a user's own file) is refused before
// any work starts, so a mistyped --out never destroys it.

#include <filesystem>
#include <string>

namespace triwalk {

enum class OutputKind {
  Selection,         // decimate --out, tiles stitch --out
  Evaluation,        // eval --json
  RenderStatistics,  // render --stats
  Png,               // region --out, view --screenshot
  Video,             // render --video
  CameraPath,        // view --record
};

// The "format" field a JSON output kind carries (triwalk-selection, ...);
// the writers put it in, the check reads it. Empty for the other kinds.
std::string outputFormat(OutputKind kind);

// Empty when path may be replaced by an output of this kind; else the
// problem in words ("PATH exists and is not a triwalk selection; refusing
// to overwrite it").
std::string foreignOutputProblem(const std::filesystem::path& path, OutputKind kind);

}  // namespace triwalk
