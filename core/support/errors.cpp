#include "core/support/errors.h"

#include <cstdio>
#include <cstdlib>

namespace triwalk {

void failCheck(const char* condition, const char* file, int line, const std::string& message) {
  std::fprintf(stderr, "triwalk: internal error at %s:%d: check '%s' failed: %s\n", file, line,
               condition, message.c_str());
  std::abort();
}

}  // namespace triwalk
