#pragma once
// selection.json: which samples were kept, their triangles, and for edge
// collapse the dense triangulation and the collapse log, so any prefix of
// the decimation can be replayed (the viewer steps through it).
//
// {
//   "format": "triwalk-selection", "version": 1,
//   "method": "edge_collapse",
//   "dataset": {"scene": "builtin", "samples": 450},
//   "settings": {...}, "stop_reason": "...", "next_cost": 1.91,
//   "samples": [ids], "triangles": [[id, id, id], ...]        (counter-clockwise)
//   "initial_triangles": [...],
//   "collapses": [{"first": id, "second": id, "placement": id, "kind": "midpoint",
//                  "cost": 0.41, "error": 1.2, "removed": [[...]], "added": [[...]]}, ...,
//                 {"first": id, "placement": id, "kind": "relocation", "cost": 1.56, ...}]
// }
// The log's collapses lead from the dense triangulation to the decimated
// mesh; relocations (the refinement after it, no "second") follow them and
// keep the sample count; their cost is the mean dense-sample error after.
// A collapse's "error" is what the threshold was compared with (see
// CollapseCost; the cost when absent).
// Ids are the data set's sample ids; in memory everything is sample indices.

#include "core/io/dataset.h"
#include "core/io/json_fields.h"
#include "core/selection/edge_collapse_decimator.h"
#include "core/selection/selection_refinement.h"
#include "core/selection/triangle_error.h"

#include <nlohmann/json.hpp>

#include <span>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace triwalk {

// Thresholds a selection file can hold (a threshold that overflows to
// infinity would be written as null): past a million times the dense
// error, or an absolute 1e9 (E stays below 1.1e8), nothing is refused.
inline constexpr OptionRange kRelativeErrorRange{1e-6f, 1e6f};
inline constexpr OptionRange kMaxErrorRange{1e-9f, 1e9f};

constexpr int kSelectionFormatVersion = 1;

struct Selection {
  std::string method;
  std::vector<int> samples;
  std::vector<Triangle> triangles;
  std::vector<Triangle> initialTriangles;  // edge collapse only
  std::vector<Collapse> collapses;         // edge collapse only
  std::string stopReason;
  double nextCost = 0.0;
  nlohmann::json settings = nlohmann::json::object();
  // What the decimation ran with, where the file says, so that the viewer
  // continues it the same way. The errors (describeSelectionErrors), in
  // files that name any of them: a field the file predates takes
  // decimate's default (the width: errorWidthFor's for the data set); the
  // layer cache is left to the reader. The collapse options
  // (describeDecimationOptions), in files that name the cost; options a
  // file predates take their defaults.
  std::optional<TriangleErrorSettings> errors;
  std::optional<DecimationOptions> decimation;
  // The threshold the decimation stopped at (the settings' max_error, the
  // absolute error it compared collapses with) and, when it came from one,
  // the factor of the dense triangulation's mean error (relative_error);
  // 0: none said.
  double maxError = 0.0, relativeError = 0.0;
};

// A selection file's settings for the collapse options (the stopping rule
// aside: a continued decimation sets its own).
nlohmann::json describeDecimationOptions(const DecimationOptions& options);

// A selection file's settings for the errors its decimation read: the
// error panorama (error_width, error_stride), the triangles' destinations,
// and every warp, blend, hole and error option, by the names of the
// options that set them.
nlohmann::json describeSelectionErrors(const TriangleErrorSettings& errors);

// The readers of those settings (the options decimate wrote them from):
// what a continued decimation and a tile of a tiled one run with. Throw
// InputError naming the file and field. readSelectionErrors: nothing if
// the settings name no error option.
DecimationOptions readDecimationOptions(const JsonObject& settings);
std::optional<TriangleErrorSettings> readSelectionErrors(const JsonObject& settings, const Dataset& dataset);
RefinementOptions readRefinementOptions(const JsonObject& settings);
// A threshold (max_error, relative_error): 0 (none, also when missing) or
// within range.
double readThreshold(const JsonObject& settings, const std::string& key, OptionRange range);

// Writes atomically.
void writeSelection(const std::filesystem::path& path, const Selection& selection, const Dataset& dataset);

// Reads and validates against the data set: known ids, triangles over kept
// samples, counter-clockwise, the log replays to the final triangles.
Selection readSelection(const std::filesystem::path& path, const Dataset& dataset);

// The selection's triangles as a mesh over the data set's positions.
ViewMesh selectionMesh(const Selection& selection, const Dataset& dataset);

// Triangles as a mesh over the data set's positions and walkable region
// (which serves positions outside every triangle, see ViewMesh::locate).
ViewMesh datasetTriangles(const Dataset& dataset, std::vector<Triangle> triangles);

// (x, y) of every sample, by index.
std::vector<glm::dvec2> samplePositions(const Dataset& dataset);

// The Delaunay triangulation of the given samples (all when empty) over
// the data set's positions, keeping the triangles inside its walkable
// region (see ViewMesh::delaunay). Errors name subject.
ViewMesh datasetMesh(const Dataset& dataset, std::span<const int> samples, const std::string& subject);

}  // namespace triwalk
