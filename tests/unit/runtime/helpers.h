// Small states and helpers shared by the runtime tests.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <utility>

#include "smachac/runtime/runtime.h"

namespace smachac::runtime::testing {

/// A state that returns `outcome` (declared as its only outcome unless `outcomes` is given).
inline std::unique_ptr<LambdaState> returns(std::string outcome, Keys outcomes = {}) {
  if (outcomes.empty()) outcomes.push_back(outcome);
  return std::make_unique<LambdaState>(StateSpec{.outcomes = std::move(outcomes)},
                                       [outcome](UserData&) { return outcome; });
}

/// A state that waits for a preempt (up to `limit`), then returns `preempted`, else `done`.
inline std::unique_ptr<LambdaState> waitsForPreempt(
    std::chrono::duration<double> limit = std::chrono::seconds(20)) {
  return std::make_unique<LambdaState>(StateSpec{.outcomes = {"done", "preempted"}},
                                       [limit](State& self, UserData&) -> std::string {
                                         if (!self.waitForPreempt(limit)) return "done";
                                         self.servicePreempt();
                                         return "preempted";
                                       });
}

/// Seconds since `start`.
inline double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace smachac::runtime::testing
