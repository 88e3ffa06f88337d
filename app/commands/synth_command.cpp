// `triwalk synth`: reconstruct a view from chosen references with the CPU
// reference warp and, where ground truth exists, measure R, B, E.

#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "app/setup/quality_options.h"
#include "app/setup/view_ids.h"
#include "core/image/color.h"
#include "core/image/image_annotation.h"
#include "core/io/dataset.h"
#include "core/io/png_io.h"
#include "core/io/staged_directory.h"
#include "core/support/errors.h"
#include "core/support/progress.h"
#include "core/synthesis/judged_reconstruction.h"
#include "core/synthesis/simplified_mesh_store.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <numeric>
#include <optional>

namespace triwalk {

namespace {

// The view from references at `at`, judged against truth when there is one.
JudgedReconstruction reconstruct(const Dataset& dataset, const std::vector<int>& references, glm::vec3 at, int width,
                           const Panorama* truth, const SynthesisOptions& synthesis, const ErrorOptions& errorOptions) {
  std::vector<std::unique_ptr<WarpSource>> sources;
  std::vector<const WarpSource*> pointers;
  SimplifiedMeshStore meshStore(dataset);
  for (int index : references) {
    const ViewRecord& record = dataset.sample(index);
    const Panorama panorama = dataset.loadView(record, width);
    sources.push_back(std::make_unique<WarpSource>(meshStore.source(record, panorama, synthesis.warp)));
    pointers.push_back(sources.back().get());
  }
  const int destinationWidth = sources.front()->width();
  if (truth) {
    return reconstructAndJudge(pointers, at, destinationWidth, toDisplayColors(truth->color), synthesis, errorOptions);
  }
  JudgedReconstruction result;
  result.view = synthesizeView(pointers, DestinationCamera::panorama(at, destinationWidth, destinationWidth / 2),
                               synthesis);
  return result;
}

// Sample indices ordered by distance to a point in x, y (ties by index).
std::vector<int> nearestSamples(const Dataset& dataset, glm::vec3 point, int count) {
  std::vector<int> order(size_t(dataset.sampleCount()));
  std::iota(order.begin(), order.end(), 0);
  auto distance = [&](int i) { return glm::length(glm::vec2(dataset.sample(i).position) - glm::vec2(point)); };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return distance(a) < distance(b); });
  order.resize(size_t(std::min(count, dataset.sampleCount())));
  return order;
}

const ViewRecord* viewAt(const Dataset& dataset, glm::vec3 point) {
  for (const auto* views : {&dataset.manifest().samples, &dataset.manifest().probes}) {
    for (const ViewRecord& view : *views) {
      if (glm::length(view.position - point) < 1e-3f) return &view;
    }
  }
  return nullptr;
}

void probeStudy(const Dataset& dataset, int width, const SynthesisOptions& synthesis, const ErrorOptions& errorOptions) {
  if (dataset.probeCount() == 0) throw InputError(dataset.manifestPath().string(), "the data set has no probes");
  std::printf("| probe | position | E, 1 nearest | E, 3 nearest | R1 | R3 | B1 %% | B3 %% |\n|---|---|---|---|---|---|---|---|\n");
  double sum1 = 0.0, sum3 = 0.0;
  int better = 0;
  ProgressReporter progress("probes", size_t(dataset.probeCount()));
  for (int p = 0; p < dataset.probeCount(); ++p) {
    throwIfInterrupted();
    const ViewRecord& probe = dataset.probe(p);
    const Panorama truth = dataset.loadView(probe, width);
    const JudgedReconstruction one =
        reconstruct(dataset, nearestSamples(dataset, probe.position, 1), probe.position, width, &truth, synthesis, errorOptions);
    const JudgedReconstruction three =
        reconstruct(dataset, nearestSamples(dataset, probe.position, 3), probe.position, width, &truth, synthesis, errorOptions);
    std::printf("| p%d | (%.2f, %.2f) | %.3f | %.3f | %.4f | %.4f | %.2f | %.2f |\n", probe.id, probe.position.x,
                probe.position.y, one.error.total, three.error.total, one.error.rms, three.error.rms,
                one.error.badPercent, three.error.badPercent);
    sum1 += one.error.total;
    sum3 += three.error.total;
    better += three.error.total < one.error.total;
    progress.advance();
  }
  progress.finish();
  std::printf("\nmean E: 1 nearest %.3f, 3 nearest %.3f; 3 nearest lower at %d of %d probes\n",
              sum1 / dataset.probeCount(), sum3 / dataset.probeCount(), better, dataset.probeCount());
}

}  // namespace

void registerSynthCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, out, truth;
    std::vector<std::string> references;
    std::vector<float> at;
    int width = 0;
    bool allProbes = false;
    QualityArguments quality;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("synth", "Reconstruct a view from reference samples with the CPU warp");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--refs", arguments->references, "Reference sample ids, e.g. 12,13,27")->delimiter(',');
  command->add_option("--at", arguments->at, "Destination position x,y,z in metres; default: the --truth view's")
      ->delimiter(',')->expected(3)->check(coordinate());
  command->add_option("--truth", arguments->truth, "Ground truth view (sample id or pN); default: a view at --at");
  CLI::Option* out = command->add_option("--out", arguments->out, "Directory for reconstruction, truth and heatmap PNGs")
                         ->check(writableDirectory());
  command->add_option("--width", arguments->width, "Work at this panorama width (divides the data set's); 0 = full")
      ->capture_default_str();
  // The table writes no images, so an --out beside it would be ignored in silence.
  command->add_flag("--all-probes", arguments->allProbes,
                    "For every probe: E from the 1 and the 3 nearest samples, as a table (no images)")
      ->excludes(out);
  addQualityOptions(*command, arguments->quality, HoleMode::Fill);

  command->callback([arguments] {
    const Arguments& a = *arguments;
    const Dataset dataset = Dataset::open(a.dataset);
    const SynthesisOptions synthesis = synthesisOptions(a.quality);
    const ErrorOptions errors = errorOptions(a.quality);
    dataset.downsamplingFactor(a.width, "--width");
    std::printf("%s\n", describeQuality(synthesis, errors).c_str());
    InterruptScope interruptScope;
    if (a.allProbes) {
      probeStudy(dataset, a.width, synthesis, errors);
      return;
    }
    if (a.references.empty() || (a.at.empty() && a.truth.empty())) {
      throw InputError("synth", "give --refs and --at (or --truth, whose position it is), or --all-probes");
    }
    if (a.references.size() > 8) throw InputError("--refs", "at most 8 references");
    std::vector<int> references;
    for (const std::string& name : a.references) references.push_back(findSampleIndex(dataset, name, "--refs"));
    const ViewRecord* named = a.truth.empty() ? nullptr : &findView(dataset, a.truth, "--truth");
    const glm::vec3 at = a.at.empty() ? named->position : glm::vec3(a.at[0], a.at[1], a.at[2]);
    const ViewRecord* truthView = named ? named : viewAt(dataset, at);
    std::unique_ptr<Panorama> truth;
    if (truthView) truth = std::make_unique<Panorama>(dataset.loadView(*truthView, a.width));

    // --out is replaced as a whole when this run is done (an earlier synth's
    // folder may be; any other non-empty folder is refused before the work).
    std::optional<StagedDirectory> staging;
    if (!a.out.empty()) staging.emplace(a.out, "reconstruction.png", "an earlier synth");
    auto write = [&](const std::string& name, const Rgb8Image& image) {
      staging->writeFile(name, [&](const std::filesystem::path& path) { writePng(path, image); });
    };
    const JudgedReconstruction result = reconstruct(dataset, references, at, a.width, truth.get(), synthesis, errors);
    const BlendedView& blended = result.view.blended;
    const double pixels = double(blended.hole.size());
    std::printf("reconstructed %dx%d at (%.3f, %.3f, %.3f) from %zu references; holes %.3f%% of pixels before "
                "filling, %.3f%% left (--holes %s)\n",
                blended.color.width, blended.color.height, at.x, at.y, at.z, references.size(),
                100.0 * double(result.view.fill.holesBefore) / pixels, 100.0 * double(result.view.fill.unfilled) / pixels,
                holeModeName(synthesis.holes));
    if (staging) write("reconstruction.png", displayImage(blended, synthesis.holes));
    if (!truth) {
      if (staging) staging->commit();
      std::printf("no ground truth at this position (give --truth to compare)\n");
      return;
    }
    std::printf("truth %s: R %.5f  B %.3f%%  E %.4f\n", truthView->file.c_str(), result.error.rms,
                result.error.badPercent, result.error.total);
    if (staging) {
      write("truth.png", toDisplayImage(truth->color));
      write("heatmap.png", withColourBar(heatmapImage(result.perPixel, 0.25f), 0.25f, "per-pixel RMS colour difference to the truth"));
      staging->commit();
      std::printf("wrote reconstruction.png, truth.png, heatmap.png (per-pixel RMS difference, red = 0.25) to %s\n",
                  a.out.c_str());
    }
  });
}

}  // namespace triwalk
