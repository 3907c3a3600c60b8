// process_exit.h: _exit after flushing, where the exit handlers cost about 50 K instructions
// of a cold compile (thread-local object pools, CLI11's validators), and the template
// engines' memory left to it (about 90 K more).
#include "tools/smachac/process_exit.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "backends/tmpl/environment.h"

namespace smachac::driver {

void leaveMemoryToProcessExit() {
#ifndef SMACHAC_SANITIZED
  tmpl::Environment::leaveToProcessExit();
#endif
}

int finishProcess(int code) {
  // std::cout may have a buffer of its own (lsp unties it from stdio).
  std::cout.flush();
  std::cerr.flush();
  std::clog.flush();
  std::fflush(nullptr);
#ifndef SMACHAC_SANITIZED
  _exit(code);
#endif
  return code;
}

}  // namespace smachac::driver
