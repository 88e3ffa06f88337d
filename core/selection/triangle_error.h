#pragma once
// The error of a triangle of reference views (docs/DESIGN.md, "Triangle
// error"): warp its three vertices' panoramas to destinations
// inside it, blend, and compare with the panoramas captured there
// (E = alpha R + beta B). A destination is the nearest dense sample to a
// point that is not a vertex of the triangle. The paper (and docs/DESIGN.md)
// use the centroid alone; "quadrature" also uses the centroids of the
// three sub-triangles (centroid, two vertices), weighted equally, so that
// long or large triangles are judged over their area, not at one point.
// Everything is held at the decimation resolution in memory.

#include "core/geometry/planar_geometry.h"
#include "core/io/dataset.h"
#include "core/synthesis/judged_reconstruction.h"
#include "core/synthesis/reconstruction_error.h"
#include "core/synthesis/view_synthesis.h"
#include "core/synthesis/warp_layer_cache.h"

#include <atomic>
#include <map>
#include <mutex>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace triwalk {

// Where decimation gets triangle errors from: the data set here, synthetic
// costs in unit tests.
class TriangleErrorSource {
public:
  virtual ~TriangleErrorSource() = default;
  // E of each triangle (sample indices), in order; may run in parallel.
  virtual void computeErrors(std::span<const Triangle> triangles, std::span<double> errors) = 0;
};

// E of reconstructing a dense sample from a triangle's three samples: the
// data set (DatasetTriangleErrors) or synthetic errors in unit tests.
struct SampleReconstruction {
  Triangle references;  // sorted sample indices
  int destination = -1;
  auto operator<=>(const SampleReconstruction&) const = default;
};

class ReconstructionErrorSource {
public:
  virtual ~ReconstructionErrorSource() = default;
  // E of each request, in order; may run in parallel.
  virtual void computeReconstructionErrors(std::span<const SampleReconstruction> requests, std::span<double> errors) = 0;
};

// Centroid: the paper's. Quadrature: also the three sub-triangle
// centroids. Interior: the dense samples inside the triangle, up to
// kMaxInteriorDestinations spread by farthest-point picking (the centroid
// sample when none is inside), the estimate the paper names ideal.
enum class TriangleDestinations { Centroid, Quadrature, Interior };
constexpr int kMaxInteriorDestinations = 8;

// Parses "centroid", "quadrature" or "interior"; throws InputError.
TriangleDestinations parseTriangleDestinations(const std::string& name);
const char* triangleDestinationsName(TriangleDestinations destinations);

// Errors at most this wide unless asked (the width the main job and
// docs/history/RESULTS-2026-11.md measure at); commands pick the largest width not above it
// that divides the data set's (Dataset::largestWidthAtMost).
inline constexpr int kDefaultErrorWidth = 256;
// The error width for a request: `requested` if given (> 0), else that
// default; throws InputError naming the setting error_width if it does not divide the
// data set's width.
int errorWidthFor(const Dataset& dataset, int requested);

// What decimation and evaluation measure the error on unless asked: the
// raw warp, holes counted as black and bad (the paper's); docs/history/RESULTS-2026-11.md,
// "Hole filling", has both measured.
inline constexpr HoleMode kDefaultErrorHoles = HoleMode::Black;

// The blend weights the selection prices collapses and refinement steps
// with unless asked (decimate, the suite's selections, the viewer's live
// decimation): the paper's inverse distance, while frames and evaluation
// blend by reliability. The reliability weights lean on whichever
// reference sampled a surface best, so they hide how far a view is from
// its references; the selection's job is to place references, and the
// distance weights keep that cost visible. Measured on the six-scene
// suite: decimating with distance and evaluating with reliability beat
// decimating with reliability on 11 of 18 rows (docs/history/RESULTS-2026-11.md, "Rerun
// with blend weights by reliability").
inline constexpr BlendWeights kSelectionBlendWeights = BlendWeights::Distance;

// The source meshes the selection warps with unless asked (the same
// commands; evaluation and frames choose their own, the grid). Simplified
// meshes make an error 1.65x faster at 256x128 and the main job's
// decimation a quarter shorter, with selections as good on the held-out
// probes of the suite's six scenes (+0.2% +- 0.8% over its 18 rows,
// paired; docs/history/RESULTS-2026-11.md, "Selecting on simplified meshes").
inline constexpr SourceMesh kSelectionSourceMesh = SourceMesh::Simplified;

// The lattice the selection's errors are read on unless asked
// (TriangleErrorSettings::stride): decimate, the suite's selections, the
// viewer's live decimation and bench decimate.
inline constexpr int kSelectionErrorStride = 1;

// A command's synthesis options with the selection's defaults on top (the
// error's holes, kSelectionSourceMesh, kSelectionBlendWeights), the rest
// (stretch test, tolerances) kept: the one place the selection's defaults
// are applied, by decimate's and the suite's option defaults, the viewer's
// live decimation and bench decimate alike.
SynthesisOptions withSelectionDefaults(SynthesisOptions synthesis);

// "errors at 256x128", and "(every other row and column)" on a lattice: how
// reports name the errors a selection is made or judged with.
std::string describeErrorPanorama(int width, int stride);

struct TriangleErrorSettings {
  int width = kDefaultErrorWidth;  // panorama width the errors are computed at
  // The errors the selection reads from cached layers (computeErrors,
  // computeReconstructionErrors) on the lattice of every stride-th row and
  // column of that panorama: a power of two, 1 for every pixel. errorAt,
  // which judges selections, always reads every pixel.
  int stride = 1;
  // Warped layers kept for reuse; none: budgetByMachineMemory once the
  // views are loaded, so that it counts what they took.
  std::optional<size_t> layerCacheBytes;
  TriangleDestinations destinations = TriangleDestinations::Centroid;
  SynthesisOptions synthesis{.warp = {}, .blend = {}, .holes = kDefaultErrorHoles};
  ErrorOptions error;
};

// The errors a selection is made with when nothing says otherwise, for
// panoramas of panoramaSize: the widest error width not above
// kDefaultErrorWidth that divides it, kSelectionErrorStride, and
// withSelectionDefaults over TriangleErrorSettings' own. A selection
// file's missing fields, the viewer's live decimation without a selection
// file, the stores capture and import keep, and bench decimate start from
// it; decimate's options default to the same values.
TriangleErrorSettings selectionErrorDefaults(glm::ivec2 panoramaSize);
TriangleErrorSettings selectionErrorDefaults(const Dataset& dataset);

// Throws InputError naming the stride (strideName: the option, or a
// selection file's field) unless settings.stride is a power of two dividing
// the error panorama's height, and 1 with the hole fill (which needs every
// pixel; holesName says where the holes are chosen).
void checkErrorStride(const TriangleErrorSettings& settings, const std::string& strideName = "error_stride",
                      const std::string& holesName = "holes");

// Which views DatasetTriangleErrors loads: a selection reads only the
// samples; the probes are held out for judging one (eval, the suite's
// evaluation), and on the main job they are a third of the views to load.
enum class LoadedViews { Samples, SamplesAndProbes };

// Where DatasetTriangleErrors found its views: copies at the error width
// read from the data set's store or made from the EXR files, simplified
// meshes read or simplified (core/io/downsampled_panorama_store.h,
// core/synthesis/simplified_mesh_store.h).
struct ViewLoads {
  int panoramasRead = 0, panoramasDownsampled = 0;
  int meshesRead = 0, meshesSimplified = 0;
};

// The destination samples of a triangle with their weights (summing to 1),
// from the samples' positions alone: for each point (centroid, sub-triangle
// centroids), the nearest sample that is not a vertex (ties: the lower
// index); interior: the samples inside, spread (see kMaxInteriorDestinations).
std::vector<std::pair<int, double>> triangleDestinations(std::span<const glm::dvec2> positions, const Triangle& triangle,
                                                         TriangleDestinations kind);

class DatasetTriangleErrors final : public TriangleErrorSource, public ReconstructionErrorSource {
public:
  // Loads every sample (and, if asked, every probe) at the settings' width,
  // in parallel, with progress; throws InputError for bad files.
  DatasetTriangleErrors(const Dataset& dataset, const TriangleErrorSettings& settings, LoadedViews views, bool quiet);

  void computeErrors(std::span<const Triangle> triangles, std::span<double> errors) override;
  void computeReconstructionErrors(std::span<const SampleReconstruction> requests, std::span<double> errors) override;

  // triangleDestinations of the data set's samples, as the settings choose.
  std::vector<std::pair<int, double>> destinationsOf(const Triangle& triangle) const {
    return triangleDestinations(positions_, triangle, settings_.destinations);
  }

  // Reconstruction of an arbitrary position from reference samples at the
  // error width, judged against a panorama's display colors (every pixel,
  // whatever the stride).
  JudgedReconstruction reconstruct(std::span<const int> references, glm::vec3 position, const ColorImage& truthDisplay,
                                   PerPixelError perPixel = PerPixelError::Kept) const;
  ReconstructionError errorAt(std::span<const int> references, glm::vec3 position, const ColorImage& truthDisplay) const {
    return reconstruct(references, position, truthDisplay, PerPixelError::Skipped).error;
  }

  const Dataset& dataset() const { return dataset_; }
  const TriangleErrorSettings& settings() const { return settings_; }
  const ColorImage& sampleDisplay(int sample) const { return sampleDisplay_[size_t(sample)]; }
  const ColorImage& probeDisplay(int probe) const;  // needs LoadedViews::SamplesAndProbes
  const WarpSource& source(int sample) const { return *sources_[size_t(sample)]; }
  uint64_t evaluations() const { return evaluations_; }
  const WarpLayerCache& layerCache() const { return layerCache_; }
  const ViewLoads& loads() const { return loads_; }

private:
  // E of a triangle reconstructing a destination sample, from cached layers.
  double sampleError(const Triangle& triangle, int destination);

  const Dataset& dataset_;
  TriangleErrorSettings settings_;
  std::vector<std::unique_ptr<WarpSource>> sources_;
  std::vector<ColorImage> sampleDisplay_;
  std::vector<ColorImage> probeDisplay_;
  std::vector<glm::dvec2> positions_;
  std::atomic<uint64_t> evaluations_{0};
  WarpLayerCache layerCache_;
  ViewLoads loads_;
};

}  // namespace triwalk

namespace triwalk {

// Remembers every triangle error another source computed, so that a new
// decimator (the viewer rebuilds one after stepping back) starts warm.
// Thread-safe.
class CachingTriangleErrors final : public TriangleErrorSource {
public:
  explicit CachingTriangleErrors(TriangleErrorSource& source) : source_(source) {}
  void computeErrors(std::span<const Triangle> triangles, std::span<double> errors) override;

private:
  TriangleErrorSource& source_;
  std::mutex mutex_;
  std::map<Triangle, double> known_;  // by sorted vertices
};

// The same for dense-sample reconstructions: shared by the decimation, the
// refinement after it and the viewer's decimators. Thread-safe.
class CachingReconstructionErrors final : public ReconstructionErrorSource {
public:
  explicit CachingReconstructionErrors(ReconstructionErrorSource& source) : source_(source) {}
  void computeReconstructionErrors(std::span<const SampleReconstruction> requests, std::span<double> errors) override;

private:
  ReconstructionErrorSource& source_;
  std::mutex mutex_;
  std::map<SampleReconstruction, double> known_;
};

}  // namespace triwalk
