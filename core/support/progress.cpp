#include "core/support/progress.h"

#include "core/support/errors.h"

#include <csignal>
#include <cstdio>

#include <unistd.h>

namespace triwalk {

namespace {

volatile std::sig_atomic_t gInterruptRequested = 0;
std::atomic<int> gScopeDepth{0};

extern "C" void onInterruptSignal(int signal) {
  if (gInterruptRequested) {
    // Second request: give up waiting for a clean stop.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  gInterruptRequested = 1;
}

}  // namespace

InterruptScope::InterruptScope() {
  if (gScopeDepth++ == 0) {
    std::signal(SIGINT, onInterruptSignal);
    std::signal(SIGTERM, onInterruptSignal);
  }
}

InterruptScope::~InterruptScope() {
  if (--gScopeDepth == 0) {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
}

bool interruptRequested() { return gInterruptRequested != 0; }
void requestInterrupt() { gInterruptRequested = 1; }
void clearInterrupt() { gInterruptRequested = 0; }

void throwIfInterrupted() {
  if (interruptRequested()) throw Interrupted();
}

std::string formatDuration(double seconds) {
  if (!(seconds >= 0.0) || seconds > 1e7) return "--:--";
  const long total = long(seconds + 0.5);
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, (total / 60) % 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

ProgressReporter::ProgressReporter(std::string label, size_t total, bool quiet)
    : label_(std::move(label)), total_(total), quiet_(quiet), interactive_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), lastPrint_(start_) {}

ProgressReporter::~ProgressReporter() { finish(); }

double ProgressReporter::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressReporter::advance(size_t count) {
  done_ += count;
  const auto now = std::chrono::steady_clock::now();
  // A terminal gets a live line; a log gets a line every few seconds.
  const auto interval = interactive_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(5000);
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (lock.owns_lock() && !finished_ && now - lastPrint_ >= interval && (total_ == 0 || done_ < total_)) {
    lastPrint_ = now;
    print(false);
  }
}

void ProgressReporter::setStatus(const std::string& status) {
  std::lock_guard lock(mutex_);
  status_ = status;
}

void ProgressReporter::setTotal(size_t total, std::string scope) {
  std::lock_guard lock(mutex_);
  total_ = total;
  scope_ = std::move(scope);
}

void ProgressReporter::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  print(true);
}

void ProgressReporter::print(bool final) {
  if (quiet_) return;
  const std::string text = line(final);
  if (interactive_) {
    std::fprintf(stderr, "\r\033[K%s%s", text.c_str(), final ? "\n" : "");
  } else {
    std::fprintf(stderr, "%s\n", text.c_str());
  }
  std::fflush(stderr);
}

std::string ProgressReporter::line(bool final) const {
  const size_t done = done_;
  const double elapsed = elapsedSeconds();
  const double rate = elapsed > 0.0 ? double(done) / elapsed : 0.0;
  std::string line = label_ + ": " + std::to_string(done);
  if (total_ > 0) line += "/" + std::to_string(total_);
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, "  %.1f/s  elapsed %s", rate, formatDuration(elapsed).c_str());
  line += numbers;
  if (!final && total_ > 0 && rate > 0.0 && done < total_) {
    line.append("  left ").append(formatDuration(double(total_ - done) / rate));
    if (!scope_.empty()) line.append(" of ").append(scope_);
  }
  if (!status_.empty()) line.append("  ").append(status_);
  return line;
}

}  // namespace triwalk
