// The failure path of SMACHAC_CHECK.
#include "ir/support/check.h"

#include <cstdio>
#include <cstdlib>

namespace smachac {

void checkFailed(const char* condition, const char* message, const char* file, int line) {
  std::fprintf(stderr, "smachac: internal compiler error: %s (%s) at %s:%d\n", message, condition,
               file, line);
  std::fflush(stderr);
  std::abort();
}

}  // namespace smachac
