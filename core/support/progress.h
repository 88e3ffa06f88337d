#pragma once
// Progress of long work on the terminal (count, rate, time left) and clean
// interruption: Ctrl-C sets a flag that long loops poll between units of
// work, so they stop without writing partial output.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <span>
#include <string>
#include <vector>

namespace triwalk {

// While one exists, SIGINT/SIGTERM request a stop instead of killing the
// process; a second Ctrl-C kills it as usual.
class InterruptScope {
public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

bool interruptRequested();
void requestInterrupt();  // as if Ctrl-C was pressed (tests, viewer)
void clearInterrupt();
// Throws Interrupted when a stop was requested.
void throwIfInterrupted();

class ProgressReporter {
public:
  // total may be 0 when unknown (no time left is shown then).
  ProgressReporter(std::string label, size_t total, bool quiet = false);
  ~ProgressReporter();

  void advance(size_t count = 1);  // thread-safe
  void setStatus(const std::string& status);
  // scope, if given, says what total counts when it is not the whole
  // work (a refinement's pass: "pass 3"), and the time left is shown as
  // of it ("left 0:05 of pass 3"), not as if the work ended there.
  void setTotal(size_t total, std::string scope = {});
  // The line print() shows (final: without the time left). Unlike the
  // setters it takes no lock (print holds it): call it from the thread
  // that sets the total and status.
  std::string line(bool final) const;
  void finish();
  double elapsedSeconds() const;
  size_t done() const { return done_; }
  bool quiet() const { return quiet_; }

private:
  void print(bool final);

  std::string label_;
  std::atomic<size_t> done_{0};
  size_t total_ = 0;
  std::string scope_;
  bool quiet_ = false;
  bool interactive_ = false;
  bool finished_ = false;
  std::string status_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastPrint_;
  std::mutex mutex_;
};

std::string formatDuration(double seconds);

// Values for independent requests: compute(span<const Request>,
// span<double>) fills one batch. With progress, in batches of 64 that
// advance it and stop on Ctrl-C between them (Interrupted); without, in
// one call.
template <class Request, class Compute>
std::vector<double> computeInChunks(std::span<const Request> requests, ProgressReporter* progress, Compute compute) {
  std::vector<double> computed(requests.size());
  const size_t chunk = progress ? 64 : requests.size();
  if (progress) progress->setTotal(progress->done() + requests.size());
  for (size_t first = 0; first < requests.size(); first += chunk) {
    if (progress) throwIfInterrupted();
    const size_t count = std::min(chunk, requests.size() - first);
    compute(requests.subspan(first, count), std::span<double>(computed).subspan(first, count));
    if (progress) progress->advance(count);
  }
  return computed;
}

}  // namespace triwalk
