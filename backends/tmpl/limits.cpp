// The active limits and step counter of this thread's render.
#include "backends/tmpl/limits.h"

#include <string>

#include "backends/tmpl/error.h"

namespace smachac::tmpl {
namespace {

const Limits kDefaultLimits{};
thread_local const Limits* active_limits = &kDefaultLimits;
thread_local uint64_t* active_steps = nullptr;

}  // namespace

const Limits& activeLimits() { return *active_limits; }

void checkSteps(uint64_t steps) {
  if (steps > active_limits->steps) {
    fail("template execution exceeded " + std::to_string(active_limits->steps) + " steps");
  }
}

void chargeLargeWork(size_t bytes) {
  if (active_steps == nullptr) return;
  *active_steps += bytes / kBytesPerStep;
  checkSteps(*active_steps);
}

ScopedLimits::ScopedLimits(const Limits& limits, uint64_t& steps)
    : previous_limits_(active_limits), previous_steps_(active_steps) {
  active_limits = &limits;
  active_steps = &steps;
}

ScopedLimits::~ScopedLimits() {
  active_limits = previous_limits_;
  active_steps = previous_steps_;
}

}  // namespace smachac::tmpl
