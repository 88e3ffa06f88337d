#include "app/viewer/decimation_session.h"

#include "core/image/color.h"
#include "core/io/png_io.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection_recipe.h"
#include "core/selection/tiled_selection.h"
#include "core/support/progress.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace triwalk {

namespace {

// A saved selection's recipe: the errors and the collapse options the
// viewer's decimation ran with, which it goes on with when the file is
// opened again; no threshold (the steps are the person's, a reached one is
// added when saved), no refinement (the viewer does not refine), and the
// preset of the selection it opened.
nlohmann::json savedSettings(const DecimationOptions& options, const TriangleErrorSettings& settings,
                             const std::optional<Selection>& opened) {
  SelectionRecipe recipe;
  recipe.errors = settings;
  recipe.selection.decimation = options;
  recipe.selection.decimation.maxError = 0.0;
  recipe.selection.decimation.targetSamples = 0;
  recipe.selection.refinement.radius = 0.0;
  if (opened && opened->settings.is_object()) {
    const auto preset = opened->settings.find("preset");
    if (preset != opened->settings.end() && preset->is_string()) recipe.preset = preset->get<std::string>();
  }
  return describeSelectionRecipe(recipe);
}

}  // namespace

DecimationSession::DecimationSession(const Dataset& dataset, const TriangleErrorSettings& settings, DecimationOptions options,
                                     const std::optional<Selection>& selection)
    : dataset_(dataset), settings_(settings), options_(options), savedSettings_(savedSettings(options, settings, selection)) {
  // Single steps go as far as the person asks; runs set their own limit.
  options_.maxError = 0.0;
  options_.targetSamples = 0;
  if (selection && !selection->initialTriangles.empty()) {
    initial_ = selection->initialTriangles;
    log_ = selection->collapses;
    step_ = int(log_.size());
  } else if (selection) {
    initial_ = selection->triangles;  // a baseline or hand-made selection: decimate on from it
  } else {
    initial_ = datasetMesh(dataset, {}, dataset.manifestPath().string()).triangles();
  }
  if (selection) {
    // The selection's threshold holds where it ends.
    reachedError_ = selection->maxError;
    reachedFactor_ = selection->relativeError;
    reachedStep_ = step_;
  }
  initialSamples_ = ViewMesh(samplePositions(dataset), initial_).vertexCount();
  // A capture larger than a tile is walked at once, its views read as the
  // walker needs them; the live decimation, which needs every view (GiBs
  // at this size), reads them only when first asked for.
  if (size_t(dataset.sampleCount()) <= kTileSamples) {
    startLoading();
  } else {
    publish(std::to_string(dataset.sampleCount()) + " samples: their panoramas are read when the decimation is first "
            "stepped or run (a capture this large decimates faster in tiles: triwalk decimate)");
  }
  thread_ = std::thread([this] { worker(); });
}

void DecimationSession::startLoading() {
  {
    std::lock_guard lock(mutex_);
    if (loadStarted_) return;
    loadStarted_ = true;
  }
  publish("loading panoramas for the " + describeErrorPanorama(settings_.width, settings_.stride));
  loader_ = std::thread([this] { loadErrors(); });
}

DecimationSession::~DecimationSession() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    tasks_.clear();
  }
  stopRun_ = true;
  wake_.notify_all();
  thread_.join();  // the worker is the only other thread that starts the loader
  if (loader_.joinable()) loader_.join();
}

void DecimationSession::loadErrors() {
  std::unique_ptr<DatasetTriangleErrors> loaded;
  std::string failure;
  try {
    // The probes too: the view's error overlay judges them (a few hundred panoramas at the error width).
    loaded = std::make_unique<DatasetTriangleErrors>(dataset_, settings_, LoadedViews::SamplesAndProbes, true);
  } catch (const std::exception& error) {
    failure = error.what();
  }
  {
    std::lock_guard lock(mutex_);
    loadedErrors_ = std::move(loaded);
    loadFailure_ = failure;
    loadDone_ = true;
  }
  wake_.notify_all();
}

void DecimationSession::post(std::function<void()> task) {
  {
    std::lock_guard lock(mutex_);
    tasks_.push_back(std::move(task));
    snapshot_.busy = true;
  }
  wake_.notify_all();
}

void DecimationSession::worker() {
  while (true) {
    std::function<void()> task;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || !tasks_.empty() || (loadDone_ && !errorsAdopted_); });
      if (quit_) return;
      if (loadDone_ && !errorsAdopted_) {
        // The panoramas just arrived: colour the map and say so.
        task = [this] { ensureErrors(); };
      } else {
        task = std::move(tasks_.front());
        tasks_.pop_front();
      }
    }
    try {
      task();
    } catch (const std::exception& error) {
      publish(std::string("error: ") + error.what());
    }
    std::lock_guard lock(mutex_);
    snapshot_.busy = !tasks_.empty();
    ++snapshot_.version;
  }
}

void DecimationSession::ensureErrors() {
  if (errors_) return;
  startLoading();
  std::unique_lock lock(mutex_);
  wake_.wait(lock, [&] { return quit_ || loadDone_; });
  if (!loadDone_) throw std::runtime_error("closing");
  errorsAdopted_ = true;
  if (!loadedErrors_) throw std::runtime_error(loadFailure_);
  errors_ = std::move(loadedErrors_);
  lock.unlock();
  cachedErrors_ = std::make_unique<CachingTriangleErrors>(*errors_);
  cachedSampleErrors_ = std::make_unique<CachingReconstructionErrors>(*errors_);
  // Whichever task adopted them: the map's colours, and the snapshot no longer loading.
  publish("ready");
}

void DecimationSession::ensureDecimator() {
  ensureErrors();
  if (decimator_ && decimatorStep_ == step_) return;
  decimator_ = datasetDecimator(dataset_, replayForward(initial_, log_, size_t(step_)),
                                DecimationErrors{cachedErrors_.get(), cachedSampleErrors_.get()}, options_);
  decimatorStep_ = step_;
}

// One step forward: replayed from the log, or a new collapse past its end
// (the log is cut there first if the person had stepped back).
bool DecimationSession::forwardOne() {
  if (step_ < int(log_.size())) {
    ++step_;
    return true;
  }
  ensureDecimator();
  if (!decimator_->step()) return false;
  {
    std::lock_guard lock(mutex_);  // selection() reads the log from the UI thread
    log_.resize(size_t(step_));
    log_.push_back(decimator_->log().back());
  }
  ++step_;
  decimatorStep_ = step_;
  return true;
}

void DecimationSession::publish(const std::string& status) {
  Snapshot next;
  next.triangles = replayForward(initial_, log_, size_t(step_));
  next.triangleErrors.assign(next.triangles.size(), std::numeric_limits<double>::quiet_NaN());
  if (cachedErrors_) cachedErrors_->computeErrors(next.triangles, next.triangleErrors);
  for (const Collapse& collapse : log_) next.costs.push_back(collapse.cost);
  next.step = step_;
  next.logSize = int(log_.size());
  next.firstRelocation = int(std::find_if(log_.begin(), log_.end(), [](const Collapse& c) {
                               return c.kind == PlacementKind::Relocation;
                             }) - log_.begin());
  next.samples = samplesAfter(initialSamples_, log_, size_t(step_));
  next.errorsReady = errors_ != nullptr;
  if (decimator_ && decimatorStep_ == step_ && step_ == int(log_.size())) next.nextCost = decimator_->nextCost();
  if (denseMeanError_) next.denseMeanError = *denseMeanError_;
  next.status = status;
  std::lock_guard lock(mutex_);
  next.errorsLoading = loadStarted_ && !next.errorsReady;
  next.version = snapshot_.version + 1;
  next.busy = snapshot_.busy;
  snapshot_ = std::move(next);
}

DecimationSession::Snapshot DecimationSession::snapshot() const {
  std::lock_guard lock(mutex_);
  return snapshot_;
}

void DecimationSession::stepForward(int count) {
  post([this, count] {
    int done = 0;
    while (done < count && forwardOne()) ++done;
    publish(done < count ? std::string("stopped: ") + stopReasonName(decimator_->stopReason()) : "stepped forward");
  });
}

void DecimationSession::stepBack(int count) {
  post([this, count] {
    step_ = std::max(0, step_ - count);
    publish("stepped back");
  });
}

namespace {

// "running to error 1.850: 120 collapses, 3.1/s, about 1:05 left". Only
// computed collapses count for the rate: replaying the log is instant.
std::string runStatus(const std::string& goal, int computed, std::chrono::steady_clock::time_point start,
                      size_t remaining) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double rate = seconds > 0.0 ? computed / seconds : 0.0;
  char text[160];
  std::snprintf(text, sizeof text, "running to %s: %d collapses computed, %.1f/s", goal.c_str(), computed, rate);
  std::string status = text;
  if (rate > 0.0 && remaining > 0) status += ", about " + formatDuration(double(remaining) / rate) + " left";
  return status;
}

std::string formatError(double error) {
  char text[32];
  std::snprintf(text, sizeof text, "error %.3f", error);
  return text;
}

}  // namespace

void DecimationSession::startRun(std::function<void()> run) {
  stopRun_ = false;
  post(std::move(run));
}

void DecimationSession::runToError(double maxError) {
  startRun([this, maxError] { runToErrorNow(maxError, 0.0, formatError(maxError)); });
}

void DecimationSession::runToRelativeError(double factor) {
  startRun([this, factor] {
    ensureErrors();
    if (!denseMeanError_) {
      // Over the dense triangulation, as decimate measures it, whatever the
      // session started from.
      publish("measuring the dense triangulation's mean error");
      const ViewMesh dense = datasetMesh(dataset_, {}, dataset_.manifestPath().string());
      denseMeanError_ = meanTriangleError(*cachedErrors_, dense.triangles(), true);
    }
    char goal[96];
    std::snprintf(goal, sizeof goal, "%s (%.2f x the dense mean %.3f)", formatError(factor * *denseMeanError_).c_str(),
                  factor, *denseMeanError_);
    runToErrorNow(factor * *denseMeanError_, factor, goal);
  });
}

void DecimationSession::runToErrorNow(double maxError, double factor, const std::string& goal) {
  // Relocations (the refinement after decimation) never pass an error goal:
  // their error is a mean over all dense samples, not a collapse's.
  runForward(maxError, 0, goal, [this, maxError] {
    const Collapse& next = log_[size_t(step_)];
    return next.kind != PlacementKind::Relocation && next.error > maxError;
  });
  if (stopRun_) return;
  std::lock_guard lock(mutex_);  // selection() reads them from the UI thread
  reachedError_ = maxError;
  reachedFactor_ = factor;
  reachedStep_ = step_;
}

void DecimationSession::runToSamples(int samples) {
  startRun([this, samples] {
    runForward(0.0, samples, std::to_string(samples) + " samples", [this, samples] {
      return log_[size_t(step_)].kind != PlacementKind::Relocation &&
             samplesAfter(initialSamples_, log_, size_t(step_)) <= samples;
    });
  });
}

// Replays the log while it lasts and the next logged collapse is not past
// the goal, then computes new collapses with the decimator held to the
// goal's limits.
void DecimationSession::runForward(double maxError, int targetSamples, const std::string& goal,
                                   std::function<bool()> nextLoggedIsPastGoal) {
  const DecimationOptions saved = options_;
  options_.maxError = maxError;
  options_.targetSamples = targetSamples;
  decimator_.reset();
  auto start = std::chrono::steady_clock::now();
  int computed = 0;
  while (!stopRun_) {
    const bool replay = step_ < int(log_.size());
    if (replay && nextLoggedIsPastGoal()) break;
    if (!forwardOne()) break;
    if (replay) {
      start = std::chrono::steady_clock::now();
      continue;
    }
    if (++computed % 10 == 0) publish(runStatus(goal, computed, start, decimator_->expectedRemainingCollapses()));
  }
  options_ = saved;
  decimator_.reset();
  publish(stopRun_ ? "stopped" : "reached " + goal);
}

void DecimationSession::stop() { stopRun_ = true; }

DecimationSession::Inspection DecimationSession::reconstruct(const Triangle& triangle, int destination, bool probe) {
  ensureErrors();
  Inspection inspection;
  inspection.triangle = triangle;
  inspection.destination = destination;
  inspection.probe = probe;
  const glm::vec3 position = (probe ? dataset_.probe(destination) : dataset_.sample(destination)).position;
  const ColorImage& display = probe ? errors_->probeDisplay(destination) : errors_->sampleDisplay(destination);
  const JudgedReconstruction judged = errors_->reconstruct(triangle, position, display);
  inspection.error = judged.error;
  inspection.reconstruction = displayImage(judged.view.blended, HoleMode::Mark);
  Rgb8Image truth(judged.perPixel.width, judged.perPixel.height);
  for (size_t i = 0; i < truth.pixelCount(); ++i) truth.pixels[i] = toBytes(display.pixels[i]);
  inspection.truth = std::move(truth);
  inspection.heatmap = heatmapImage(judged.perPixel, kInspectionHeatmapScale);
  return inspection;
}

void DecimationSession::inspect(const Triangle& triangle) {
  post([this, triangle] {
    ensureErrors();
    Inspection inspection = reconstruct(triangle, errors_->destinationsOf(triangle).front().first, false);
    std::lock_guard lock(mutex_);
    inspection_ = std::move(inspection);
  });
}

void DecimationSession::inspectView(const Triangle& triangle, int index, bool probe) {
  post([this, triangle, index, probe] {
    Inspection inspection = reconstruct(triangle, index, probe);
    std::lock_guard lock(mutex_);
    sampleInspection_ = std::move(inspection);
  });
}

std::optional<DecimationSession::Inspection> DecimationSession::sampleInspection() const {
  std::lock_guard lock(mutex_);
  return sampleInspection_;
}

std::optional<DecimationSession::Inspection> DecimationSession::inspection() const {
  std::lock_guard lock(mutex_);
  return inspection_;
}

Selection DecimationSession::selection() const {
  const Snapshot current = snapshot();
  Selection selection;
  selection.method = "edge_collapse";
  selection.triangles = current.triangles;
  const ViewMesh mesh(samplePositions(dataset_), current.triangles);
  selection.samples = mesh.vertices();
  selection.initialTriangles = initial_;
  std::lock_guard lock(mutex_);
  selection.collapses.assign(log_.begin(), log_.begin() + current.step);
  selection.stopReason = "saved from the viewer at step " + std::to_string(current.step);
  selection.nextCost = current.nextCost;
  selection.settings = savedSettings_;  // so that the viewer continues the saved selection the same way
  if (reachedError_ > 0.0 && current.step == reachedStep_) {
    selection.settings.update({{"max_error", reachedError_}, {"relative_error", reachedFactor_}});
  }
  return selection;
}

}  // namespace triwalk
