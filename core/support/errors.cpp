#include "core/support/errors.h"

#include <cstdio>
#include <cstdlib>

namespace triwalk {

std::string printableLine(const std::string& message, size_t maxLength) {
  std::string line;
  for (const char c : message) {
    if (line.size() >= maxLength) return line + "...";
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      line += c;
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      line += escaped;
    }
  }
  return line;
}

void failCheck(const char* condition, const char* file, int line, const std::string& message) {
  std::fprintf(stderr, "triwalk: internal error at %s:%d: check '%s' failed: %s\n", file, line,
               condition, message.c_str());
  std::abort();
}

}  // namespace triwalk
