#pragma once
// The viewer's decimation: the dense triangulation, the collapse log and
// the step the person is at. Stepping within the log replays it (instant,
// forward and back); stepping past its end computes new collapses. Work
// that needs panoramas (triangle errors, collapses, the inspector's
// reconstruction) runs on one worker thread, so the walkthrough never
// stalls; the UI reads snapshots. The panoramas at the error width load on
// a thread of their own, so stepping through the log works at once while
// they load; only the work that needs them waits.

#include "core/image/image.h"
#include "core/io/dataset.h"
#include "core/selection/edge_collapse_decimator.h"
#include "core/selection/selection.h"
#include "core/selection/triangle_error.h"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace triwalk {

// The inspection's heatmaps show a pixel's RMS colour difference from 0 to this (red).
constexpr float kInspectionHeatmapScale = 0.25f;

class DecimationSession {
public:
  // selection: continue from a saved selection (its log when it has one).
  DecimationSession(const Dataset& dataset, const TriangleErrorSettings& settings, DecimationOptions options,
                    const std::optional<Selection>& selection);
  ~DecimationSession();
  DecimationSession(const DecimationSession&) = delete;
  DecimationSession& operator=(const DecimationSession&) = delete;

  struct Snapshot {
    uint64_t version = 0;  // changes whenever anything below does
    std::vector<Triangle> triangles;
    std::vector<double> triangleErrors;  // aligned with triangles; NaN until known
    std::vector<double> costs;           // cost of each logged collapse
    int step = 0;                        // collapses applied
    int logSize = 0;
    int firstRelocation = 0;             // where the refinement starts in the log (logSize: none)
    int samples = 0;
    double nextCost = -1.0;              // of the next new collapse; -1 unknown, +inf none
    // The dense triangulation's mean triangle error, once a run to a
    // relative error has measured it; NaN before.
    double denseMeanError = std::numeric_limits<double>::quiet_NaN();
    bool errorsReady = false;            // panoramas loaded at the error width
    bool errorsLoading = false;          // being loaded (a large capture's wait until asked for)
    bool busy = false;
    std::string status;
  };
  Snapshot snapshot() const;

  void stepForward(int count);
  void stepBack(int count);
  void runToError(double maxError);
  // As decimate --relative-error: to factor times the dense triangulation's
  // mean triangle error, measured (once) first.
  void runToRelativeError(double factor);
  void runToSamples(int samples);
  void stop();  // ends a run after the current collapse

  struct Inspection {
    Triangle triangle{};
    int destination = -1;  // sample index, or probe index if probe
    bool probe = false;
    ReconstructionError error;
    Rgb8Image reconstruction, truth, heatmap;
  };
  // The triangle's reconstruction at the destination nearest its centroid (the Inspector).
  void inspect(const Triangle& triangle);
  std::optional<Inspection> inspection() const;
  // A sample or a probe reconstructed from the triangle (the view's error
  // overlay): its own slot, so that the Inspector keeps what was clicked.
  void inspectView(const Triangle& triangle, int index, bool probe);
  std::optional<Inspection> sampleInspection() const;

  // The selection at the current step, as decimate would write it.
  Selection selection() const;
  const Dataset& dataset() const { return dataset_; }

private:
  void worker();
  void loadErrors();
  void post(std::function<void()> task);
  // Posts a run; the UI thread's stop() ends it from then on.
  void startRun(std::function<void()> run);
  // Worker thread only.
  void runForward(double maxError, int targetSamples, const std::string& goal, std::function<bool()> nextLoggedIsPastGoal);
  // factor: of the dense mean error, when the threshold came from one (else 0).
  void runToErrorNow(double maxError, double factor, const std::string& goal);
  // Starts reading the samples' views on the loader thread, once.
  void startLoading();
  // Worker thread only. Starts the loader if it has not started, and waits for it.
  void ensureErrors();
  void ensureDecimator();
  bool forwardOne();
  void publish(const std::string& status);
  // Worker thread only.
  Inspection reconstruct(const Triangle& triangle, int destination, bool probe);

  const Dataset& dataset_;
  TriangleErrorSettings settings_;
  DecimationOptions options_;  // the worker's: runs change its stopping rule
  // What a saved selection's settings say it was made with, fixed at the
  // start (the UI thread saves while the worker runs).
  const nlohmann::json savedSettings_;
  std::vector<Triangle> initial_;
  int initialSamples_ = 0;  // each collapse removes one; relocations keep the count

  // Worker state.
  std::vector<Collapse> log_;
  int step_ = 0;
  std::unique_ptr<DatasetTriangleErrors> errors_;
  std::unique_ptr<CachingTriangleErrors> cachedErrors_;
  std::unique_ptr<CachingReconstructionErrors> cachedSampleErrors_;
  std::unique_ptr<EdgeCollapseDecimator> decimator_;
  int decimatorStep_ = -1;  // the step the decimator's mesh is at
  std::optional<double> denseMeanError_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> tasks_;
  Snapshot snapshot_;
  std::optional<Inspection> inspection_, sampleInspection_;
  std::atomic<bool> stopRun_{false};
  // The last error a run reached (at first the selection's threshold) and
  // the step it stopped at, as a selection file's max_error and
  // relative_error, so that a selection saved there starts "run to error"
  // there; saved at any other step, the file names no threshold.
  double reachedError_ = 0.0, reachedFactor_ = 0.0;
  int reachedStep_ = -1;
  bool quit_ = false;
  // Loader results, handed to the worker under mutex_.
  std::unique_ptr<DatasetTriangleErrors> loadedErrors_;
  std::string loadFailure_;
  bool loadStarted_ = false;
  bool loadDone_ = false;
  bool errorsAdopted_ = false;
  std::thread thread_;
  std::thread loader_;
};

}  // namespace triwalk
