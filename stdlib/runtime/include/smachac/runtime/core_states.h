// The reusable states behind SMACHA's core templates (each as its template's Python class).
//
//   CallbacksState           runs its callbacks, returns `succeeded`
//   PrintUserdataState       prints `userdata.<key>: <value>` for each input key
//   RandomOutcomeState       runs its callbacks, picks one of its outcomes (seedable)
//   ConditionalOutcomeState  runs its callbacks, returns the first outcome whose key is set
//                            and true, else `default`, and writes the choice to `outcome`
//   LogState                 prints its text on a line of its own, returns `done` (FlexBE's
//                            LogState)
//   SleepState               sleeps; when it declares `preempted`, wakes at once on preemption
//                            and returns it (SMACH allows only declared outcomes)
//
// A callback computes the value of one output key from the userdata: callbacks are keyed by
// that output key, which the state declares for them, and run in the order given (the
// script's order, which the SMACH target's state classes follow too).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "smachac/runtime/callback.h"
#include "smachac/runtime/callback_literal.h"
#include "smachac/runtime/state.h"
#include "smachac/runtime/value.h"

namespace smachac::runtime {

/// An output key and the callback computing its value.
struct KeyedCallback {
  std::string key;
  Callback callback;
  /// The key's position in its state's output keys (placeCallbacks), if known.
  std::size_t position = ~std::size_t{0};
};
/// In the order they run: `{{"n", [](rt::UserData& ud) { ... }}, ...}`. Generated code writes
/// CallbacksLiteral (callback_literal.h), which converts to it.
using Callbacks = std::vector<KeyedCallback>;

/// Runs `callbacks` in order, writing each result to its key.
void runCallbacks(const Callbacks& callbacks, UserData& userdata);
/// Finds each callback's key in `output_keys`, so that runCallbacks writes it without a search.
void placeCallbacks(Callbacks& callbacks, const Keys& output_keys);

/// Seed for RandomOutcomeStates made without one (each mixes in its path). Unset: random.
void setRandomSeed(std::optional<uint64_t> seed);
std::optional<uint64_t> randomSeed();

class CallbacksState : public State {
 public:
  explicit CallbacksState(StateSpec spec = {}, Callbacks callbacks = {});
  std::string execute(UserData& userdata) override;
  int executeAt(UserData& userdata, std::string& other) override;

 private:
  Callbacks callbacks_;
  int succeeded_;  ///< the position of `succeeded` in outcomes(), or -1
};

class PrintUserdataState : public State {
 public:
  /// Prints to `out` (nullptr: std::cout).
  explicit PrintUserdataState(StateSpec spec = {}, std::ostream* out = nullptr);
  std::string execute(UserData& userdata) override;

 private:
  std::ostream* out_;
};

class RandomOutcomeState : public State {
 public:
  /// Outcomes default to {succeeded}; writes the chosen outcome to output key `outcome`.
  explicit RandomOutcomeState(StateSpec spec = {}, Callbacks callbacks = {},
                              std::optional<uint64_t> seed = std::nullopt);
  std::string execute(UserData& userdata) override;

 private:
  Callbacks callbacks_;
  std::optional<uint64_t> seed_;
  bool seeded_ = false;
  uint64_t rng_ = 0;  ///< SplitMix64 state: the same sequence on every platform
};

class ConditionalOutcomeState : public State {
 public:
  /// Outcomes get `default` appended last; each other outcome becomes an input and output key
  /// (the condition), plus output key `outcome` (the choice).
  ConditionalOutcomeState(StateSpec spec, Callbacks callbacks = {});
  std::string execute(UserData& userdata) override;
  int executeAt(UserData& userdata, std::string& other) override;

 private:
  Callbacks callbacks_;
  std::vector<std::size_t> conditions_;  ///< per outcome but `default`: its input key position
  std::size_t outcome_key_;              ///< the position of `outcome` in outputKeys()
  std::vector<Value> choices_;           ///< per outcome: the Value written to `outcome`
};

class LogState : public State {
 public:
  /// Prints to `out` (nullptr: std::cout). Outcomes default to {done}.
  explicit LogState(std::string text, StateSpec spec = {}, std::ostream* out = nullptr);
  std::string execute(UserData& userdata) override;

 private:
  std::string text_;
  std::ostream* out_;
};

class SleepState : public State {
 public:
  explicit SleepState(double seconds, StateSpec spec = {});
  std::string execute(UserData& userdata) override;

 private:
  double seconds_;
};

}  // namespace smachac::runtime
