// The active limits and step counter of this thread's render.
#include "backends/tmpl/limits.h"

#include <string>

#include "backends/tmpl/error.h"

namespace smachac::tmpl {
namespace {

constexpr size_t kBytesPerStep = 256;

const Limits kDefaultLimits{};
thread_local const Limits* activeLimits_ = &kDefaultLimits;
thread_local uint64_t* activeSteps_ = nullptr;

}  // namespace

const Limits& activeLimits() { return *activeLimits_; }

void checkSteps(uint64_t steps) {
  if (steps > activeLimits_->steps) {
    fail("template execution exceeded " + std::to_string(activeLimits_->steps) + " steps");
  }
}

void chargeWork(size_t bytes) {
  if (activeSteps_ == nullptr || bytes < kBytesPerStep) return;
  *activeSteps_ += bytes / kBytesPerStep;
  checkSteps(*activeSteps_);
}

ScopedLimits::ScopedLimits(const Limits& limits, uint64_t& steps)
    : previousLimits_(activeLimits_), previousSteps_(activeSteps_) {
  activeLimits_ = &limits;
  activeSteps_ = &steps;
}

ScopedLimits::~ScopedLimits() {
  activeLimits_ = previousLimits_;
  activeSteps_ = previousSteps_;
}

}  // namespace smachac::tmpl
