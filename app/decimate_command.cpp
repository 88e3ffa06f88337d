// `triwalk decimate`: edge-collapse decimation of the dense triangulation,
// written as selection.json with its collapse log.

#include "app/commands.h"
#include "app/decimation_options.h"
#include "core/edge_collapse_decimator.h"
#include "core/errors.h"
#include "core/progress.h"
#include "core/selection.h"
#include "core/selection_refinement.h"

#include <chrono>
#include <cstdio>

namespace triwalk {

void registerDecimateCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, out;
    double maxError = DecimationOptions{}.maxError;
    int target = 0;
    bool oneRing = false;
    bool unweightedCost = false;
    double refineRadius = RefinementOptions{}.radius;
    bool quiet = false;
    ErrorArguments errors;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("decimate", "Select reference samples by edge-collapse decimation");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--out", arguments->out, "Selection file to write (selection.json)")->required();
  command->add_option("--max-error", arguments->maxError,
                      "Stop before a collapse whose cost exceeds this (the paper's 1.85); 0 disables")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  command->add_option("--target", arguments->target, "Stop at this many samples; 0 disables")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  command->add_flag("--one-ring", arguments->oneRing,
                    "Also try every free sample inside the two one-rings as the placement");
  command->add_flag("--unweighted-cost", arguments->unweightedCost,
                    "Edge cost as the paper's plain mean of the updated triangles' errors (default: area-weighted)");
  command->add_option("--refine-radius", arguments->refineRadius,
                      "After decimation, move references up to this far (metres) at a time while that lowers the "
                      "mean error over the dense samples; 0 disables")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  command->add_flag("--quiet", arguments->quiet, "No progress output");
  addErrorOptions(*command, arguments->errors);

  command->callback([arguments] {
    const Arguments& a = *arguments;
    if (a.maxError <= 0.0 && a.target == 0) throw InputError("decimate", "give --max-error, --target or both");
    if (a.target == 1 || a.target == 2) throw InputError("--target", "a triangle needs at least 3 samples");
    const Dataset dataset = Dataset::open(a.dataset);
    if (a.target > dataset.sampleCount()) {
      throw InputError("--target", std::to_string(a.target) + " is more than the " + std::to_string(dataset.sampleCount()) +
                                       " samples of the data set");
    }
    const TriangleErrorSettings settings = triangleErrorSettings(a.errors);
    std::printf("%s\n", describeErrorSettings(settings).c_str());
    const ViewMesh initial = ViewMesh::delaunay(samplePositions(dataset), {}, dataset.manifestPath().string());
    std::printf("dense triangulation: %d samples, %d triangles\n", initial.vertexCount(), initial.triangleCount());

    InterruptScope interruptScope;
    DatasetTriangleErrors errors(dataset, settings, a.quiet);
    DecimationOptions options;
    options.maxError = a.maxError;
    options.targetSamples = a.target;
    options.oneRingCandidates = a.oneRing;
    options.areaWeightedCost = !a.unweightedCost;
    const auto start = std::chrono::steady_clock::now();
    ProgressReporter costing("cost every edge (triangle errors)", 0, a.quiet);
    EdgeCollapseDecimator decimator(initial, errors, options, &costing);
    costing.finish();
    const double costingSeconds = costing.elapsedSeconds();
    const size_t expected = a.target > 0 ? size_t(initial.vertexCount() - a.target) : 0;
    ProgressReporter progress("collapse", expected, a.quiet);
    const StopReason reason = decimator.run(&progress);
    progress.finish();
    if (reason == StopReason::Interrupted) throw Interrupted();
    const double decimationSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const ViewMesh decimated = decimator.mesh();
    RefinementOptions refinementOptions;
    refinementOptions.radius = a.refineRadius;
    ProgressReporter refining("refine: move references", 0, a.quiet || a.refineRadius <= 0.0);
    const RefinementResult refinement = refineSelection(initial.positions(), decimated.triangles(),
                                                        errors, refinementOptions, &refining);
    refining.finish();
    const ViewMesh final(initial.positions(), refinement.triangles);

    Selection selection;
    selection.method = "edge_collapse";
    selection.samples = final.vertices();
    selection.triangles = final.triangles();
    selection.initialTriangles = initial.triangles();
    selection.collapses = decimator.log();
    selection.collapses.insert(selection.collapses.end(), refinement.moves.begin(), refinement.moves.end());
    selection.stopReason = stopReasonName(reason);
    selection.nextCost = decimator.nextCost();
    selection.settings = {{"max_error", a.maxError},
                          {"target", a.target},
                          {"one_ring", a.oneRing},
                          {"area_weighted_cost", !a.unweightedCost},
                          {"refine_radius", a.refineRadius},
                          {"error_width", settings.width},
                          {"quality", describeErrorSettings(settings)}};
    writeSelection(a.out, selection, dataset);

    const DecimationStatistics& statistics = decimator.statistics();
    std::printf("kept %d of %d samples, %d triangles; stopped: %s", final.vertexCount(), initial.vertexCount(),
                final.triangleCount(), stopReasonName(reason));
    if (std::isfinite(selection.nextCost)) std::printf(" (next cost %.3f)", selection.nextCost);
    std::printf("\n%zu collapses in %.1f s (edge costing %.1f s); triangle errors computed %llu, served from the cache "
                "%llu; stale heap entries skipped %llu\n",
                decimator.log().size(), decimationSeconds, costingSeconds, (unsigned long long)statistics.errorsComputed,
                (unsigned long long)statistics.cacheHits, (unsigned long long)statistics.staleEntriesSkipped);
    if (a.refineRadius > 0.0) {
      std::printf("refinement: %zu references moved in %d passes (radius %.2f m); mean error over the dense samples %.4f "
                  "-> %.4f; %.1f s, errors computed %llu, served from the cache %llu\n",
                  refinement.moves.size(), refinement.passes, a.refineRadius, refinement.objectiveBefore,
                  refinement.objectiveAfter, refining.elapsedSeconds(), (unsigned long long)refinement.errorsComputed,
                  (unsigned long long)refinement.cacheHits);
    }
    std::printf("warped layers computed %llu, reused %llu\n", (unsigned long long)errors.layerCache().misses(),
                (unsigned long long)errors.layerCache().hits());
    std::printf("wrote %s\n", a.out.c_str());
  });
}

}  // namespace triwalk
