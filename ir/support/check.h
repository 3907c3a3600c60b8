// Internal invariants. A failed SMACHAC_CHECK is a bug in smachac, never a problem in the
// user's script (those go through DiagnosticEmitter): it prints one line and aborts.
#pragma once

namespace smachac {

[[noreturn]] void checkFailed(const char* condition, const char* message, const char* file,
                              int line);

}  // namespace smachac

#define SMACHAC_CHECK(condition, message)                              \
  do {                                                                 \
    if (!(condition)) {                                                \
      ::smachac::checkFailed(#condition, message, __FILE__, __LINE__); \
    }                                                                  \
  } while (false)
