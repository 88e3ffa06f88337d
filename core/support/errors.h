#pragma once
// Two kinds of failure, kept apart as in TMIV (VERIFY vs ASSERT):
//  - InputError: something outside the program is wrong (a file, an option).
//    It names the subject (usually a path) and the problem; the CLI prints it
//    on one line and exits non-zero.
//  - TRIWALK_CHECK: an internal invariant. Failing it is a bug; it aborts
//    with the location so the bug is found, never silently ignored.

#include <stdexcept>
#include <string>

namespace triwalk {

class InputError : public std::runtime_error {
public:
  InputError(const std::string& subject, const std::string& problem)
      : std::runtime_error(subject + ": " + problem), subject_(subject), problem_(problem) {}

  const std::string& subject() const { return subject_; }
  const std::string& problem() const { return problem_; }

private:
  std::string subject_;
  std::string problem_;
};

// Thrown when the user asked to stop (Ctrl-C); callers unwind without
// writing partial output.
class Interrupted : public std::runtime_error {
public:
  Interrupted() : std::runtime_error("interrupted") {}
};

// A message fit for one terminal line: bytes that are not printable ASCII
// (from a corrupt file echoed in the message) written as \xNN, and the
// whole cut to about maxLength characters with "..." where it was cut.
std::string printableLine(const std::string& message, size_t maxLength = 400);

[[noreturn]] void failCheck(const char* condition, const char* file, int line, const std::string& message);

}  // namespace triwalk

#define TRIWALK_CHECK(condition, message)                                  \
  do {                                                                     \
    if (!(condition)) ::triwalk::failCheck(#condition, __FILE__, __LINE__, (message)); \
  } while (false)
