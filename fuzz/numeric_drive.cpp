#include "fuzz/numeric_drive.h"

#include "core/io/dataset.h"
#include "core/io/json_fields.h"
#include "core/selection/baselines.h"
#include "core/selection/evaluation.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection.h"
#include "core/selection/walking_distances.h"
#include "core/support/errors.h"
#include "core/synthesis/blend.h"
#include "core/synthesis/reconstruction_error.h"
#include "core/synthesis/warp.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>

namespace triwalk::fuzz {

namespace {

// The fuzzer's bytes as a stream of choices; past the end, every choice is 0.
class ByteStream {
public:
  ByteStream(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }

  // A number from the awkward table, or (past its end) the next 8 bytes as
  // any double at all.
  double number() {
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    static const std::array<double, 36> awkward = {
        std::numeric_limits<double>::quiet_NaN(), kInfinity, -kInfinity, 0.0, -0.0,
        std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
        double(std::numeric_limits<float>::denorm_min()), double(std::numeric_limits<float>::min()), 1e-30, 1e-9, 1e-6,
        1e-4, 1e-3, 0.01, 0.05, 0.5, 1.0, 2.0, 10.0, 89.0, 255.0, 1e3, 1e4, 1e5, 1e5 + 1.0, 1e6, 1e9, 1e19, 1e30,
        double(std::numeric_limits<float>::max()), 1e39, 1e308, std::numeric_limits<double>::max(), -1.0, -1e30};
    const uint8_t choice = byte();
    if (choice < awkward.size()) return awkward[choice];
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits = bits << 8 | byte();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  // Either the default (choice 0) or a number.
  std::optional<double> option() { return byte() % 2 == 0 ? std::nullopt : std::optional<double>(number()); }

private:
  const uint8_t* data_;
  size_t size_;
  size_t position_ = 0;
};

// As the command line's checks: finite (every floating-point option) and
// within the range core states for it.
bool accepted(const std::optional<double>& value, OptionRange range) {
  return !value || (std::isfinite(*value) && range.contains(*value));
}

bool acceptedNonNegative(const std::optional<double>& value) { return !value || (std::isfinite(*value) && *value >= 0.0); }

// The manifest with the chosen numbers in place of positions and yaws;
// numbers JSON cannot hold (NaN, infinities) are written as nlohmann does,
// as null, which the reader must refuse in one line too.
nlohmann::json perturbedManifest(nlohmann::json manifest, ByteStream& bytes) {
  for (const char* kind : {"samples", "probes"}) {
    for (nlohmann::json& view : manifest[kind]) {
      const uint8_t mask = bytes.byte();
      for (int axis = 0; axis < 3; ++axis) {
        if (mask & (1u << axis)) view["position"][size_t(axis)] = bytes.number();
      }
      if (mask & 8u) view["yaw_degrees"] = bytes.number();
    }
  }
  return manifest;
}

void requireFinite(double value, const char* what) {
  if (!std::isfinite(value)) {
    std::fprintf(stderr, "numeric harness: %s is %g\n", what, value);
    std::abort();
  }
}

}  // namespace

bool driveNumbers(const uint8_t* data, size_t size, const std::filesystem::path& seedDataset,
                  const std::filesystem::path& scratch) {
  const std::filesystem::path directory = scratch / "numeric_dataset";
  if (!std::filesystem::exists(directory / "samples")) {
    std::filesystem::create_directories(directory);
    std::filesystem::copy(seedDataset, directory,
                          std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing);
  }
  const nlohmann::json seedManifest = readJsonFile(seedDataset / kManifestFileName);
  ByteStream bytes(data, size);
  writeJsonFile(directory / kManifestFileName, perturbedManifest(seedManifest, bytes));

  // The options decimate and eval share, then decimate's own.
  const std::optional<double> epsilon = bytes.option(), minimumWeightDistance = bytes.option(), alpha = bytes.option(),
                              beta = bytes.option(), delta = bytes.option(), grazingAngle = bytes.option(),
                              meshTolerance = bytes.option(), relativeError = bytes.option(),
                              maxError = bytes.option(), refineRadius = bytes.option(), target = bytes.option();
  if (!accepted(epsilon, kEpsilonRange) || !accepted(minimumWeightDistance, kMinimumWeightDistanceRange) ||
      !accepted(alpha, kErrorWeightRange) || !accepted(beta, kErrorWeightRange) ||
      !accepted(delta, kBadPixelToleranceRange) || !accepted(grazingAngle, kGrazingAngleRange) ||
      !accepted(meshTolerance, kMeshToleranceRange) || !accepted(relativeError, kRelativeErrorRange) ||
      !accepted(maxError, kMaxErrorRange) || (relativeError && maxError) || !acceptedNonNegative(refineRadius) ||
      !acceptedNonNegative(target)) {
    return false;
  }

  try {
    const Dataset dataset = Dataset::open(directory);
    // decimate's target: an int option, refused at 1 and 2 and above the sample count.
    const int targetSamples = target ? int(std::min(*target, 1e9)) : 0;
    if (targetSamples == 1 || targetSamples == 2 || targetSamples > dataset.sampleCount()) return false;

    TriangleErrorSettings settings;
    settings.width = errorWidthFor(dataset, 0);
    settings.layerCacheBytes = size_t(64) << 20;
    settings.synthesis = withSelectionDefaults(settings.synthesis);
    auto apply = [&](SynthesisOptions& synthesis, ErrorOptions& error) {
      if (epsilon) synthesis.blend.epsilon = float(*epsilon);
      if (minimumWeightDistance) synthesis.blend.minimumWeightDistance = float(*minimumWeightDistance);
      if (grazingAngle) synthesis.warp.grazingAngleDegrees = float(*grazingAngle);
      if (meshTolerance) synthesis.warp.meshTolerancePixels = float(*meshTolerance);
      if (alpha) error.alpha = *alpha;
      if (beta) error.beta = *beta;
      if (delta) error.delta = *delta;
    };
    apply(settings.synthesis, settings.error);

    // decimate
    DatasetTriangleErrors selectionErrors(dataset, settings, LoadedViews::Samples, true);
    SelectionSettings selection;
    selection.decimation.maxError = maxError.value_or(0.0);
    selection.decimation.targetSamples = targetSamples;
    selection.relativeError = relativeError.value_or(!maxError && targetSamples == 0 ? kDefaultRelativeError : 0.0);
    if (refineRadius) selection.refinement.radius = *refineRadius;
    SelectionRun run = selectReferences(dataset, selectionErrors, selection, true);
    requireFinite(run.maxError, "the threshold");
    requireFinite(run.refinement.objectiveAfter, "the refined mean error");
    run.selection.settings = describeSelectionErrors(settings);
    const std::filesystem::path selectionFile = scratch / "numeric_selection.json";
    writeSelection(selectionFile, run.selection, dataset);
    const Selection selected = readSelection(selectionFile, dataset);

    // eval: its own error settings (every pixel, the evaluation's defaults) with the same options.
    if (dataset.probeCount() == 0) return true;
    TriangleErrorSettings evaluation;
    evaluation.width = settings.width;
    evaluation.layerCacheBytes = settings.layerCacheBytes;
    apply(evaluation.synthesis, evaluation.error);
    DatasetTriangleErrors evaluationErrors(dataset, evaluation, LoadedViews::SamplesAndProbes, true);
    const int count = int(selected.samples.size());
    const std::vector<glm::dvec2> positions = samplePositions(dataset);
    const MethodEvaluation collapse = evaluateMesh("edge_collapse", selectionMesh(selected, dataset), evaluationErrors);
    requireFinite(collapse.meanError, "edge collapse's mean error");
    requireFinite(collapse.probeMeanError, "edge collapse's probe mean error");
    const WalkingDistances walking(positions, dataset.walkableRegion());
    for (const std::vector<int>& baseline :
         {uniformSelection(dataset, count), kMedoidsSelection(positions, count), geodesicKMedoidsSelection(walking, count),
          farthestPointSelection(walking, count), randomSelection(dataset.sampleCount(), count, 1)}) {
      try {
        const MethodEvaluation row = evaluateMesh("baseline", datasetMesh(dataset, baseline, "baseline"), evaluationErrors);
        requireFinite(row.probeMeanError, "a baseline's probe mean error");
      } catch (const InputError&) {
        // A baseline that cannot be triangulated at this count: eval names it and goes on.
      }
    }
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace triwalk::fuzz
