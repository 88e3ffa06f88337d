#pragma once
// Runs the triwalk binary as a user would (TRIWALK_BINARY, defined by the
// command-line tests' target) and keeps what it printed.

#include "tests/test_support.h"

#include <cstdlib>
#include <string>

namespace triwalk::testing {

struct RunResult {
  int status = 0;
  std::string out, err;
};

// Runs triwalk with OpenGL: Mesa's own allocations (some in JIT code) look
// like leaks to LeakSanitizer and cannot be suppressed by name, so under
// the sanitizers such a run goes without leak detection
// (docs/RELIABILITY.md, "Sanitizers"); elsewhere the variable is ignored.
inline const std::string kTriwalkWithOpenGl = "ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\" " + std::string(TRIWALK_BINARY);

inline RunResult runTriwalk(const TemporaryDirectory& scratch, const std::string& arguments, bool openGl = false) {
  const std::filesystem::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  const std::string command =
      (openGl ? kTriwalkWithOpenGl : std::string(TRIWALK_BINARY)) + " " + arguments + " > " + out.string() + " 2> " + err.string();
  const int status = std::system(command.c_str());
  return {status, readTextFileOrEmpty(out), readTextFileOrEmpty(err)};
}

}  // namespace triwalk::testing
