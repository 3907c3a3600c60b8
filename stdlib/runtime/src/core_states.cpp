// The core states of SMACHA's templates: callbacks, print, random and conditional outcomes,
// sleep. Each follows the Python class of its SMACHA template.
#include "smachac/runtime/core_states.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <iostream>
#include <mutex>
#include <random>
#include <thread>

#include "child_workers.h"
#include "smachac/runtime/errors.h"
#include "text.h"

namespace smachac::runtime {

namespace {

constexpr const char* kSucceeded = "succeeded";
constexpr const char* kDefault = "default";
constexpr const char* kOutcomeKey = "outcome";

std::atomic<bool> g_seed_set{false};
std::atomic<uint64_t> g_seed{0};

/// Fills in the outcomes a template defaults to when the script gives none.
StateSpec withDefaultOutcome(StateSpec spec, const char* outcome = kSucceeded) {
  if (spec.outcomes.empty()) spec.outcomes.push_back(outcome);
  return spec;
}

/// One step of SplitMix64: a fixed, portable sequence for a given seed.
uint64_t splitMix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// FNV-1a, so that each unseeded random state draws its own sequence from the global seed.
uint64_t hashPath(const std::string& path) {
  uint64_t hash = 0xcbf29ce484222325ULL;
  for (unsigned char c : path) hash = (hash ^ c) * 0x100000001b3ULL;
  return hash;
}

std::mutex& printMutex() {
  static std::mutex mutex;
  return mutex;
}

/// runCallbacks() for callbacks a state placed (placeCallbacks): written by position.
void runPlaced(const Callbacks& callbacks, UserData& userdata) {
  for (const auto& entry : callbacks) userdata.setOutput(entry.position, entry.callback(userdata));
}

}  // namespace

void runCallbacks(const Callbacks& callbacks, UserData& userdata) {
  for (const auto& entry : callbacks) {
    userdata.set(entry.key, entry.position, entry.callback(userdata));
  }
}

void placeCallbacks(Callbacks& callbacks, const Keys& output_keys) {
  for (KeyedCallback& entry : callbacks) {
    entry.position = static_cast<std::size_t>(indexIn(output_keys, entry.key));
  }
}

void setRandomSeed(std::optional<uint64_t> seed) {
  g_seed.store(seed.value_or(0));
  g_seed_set.store(seed.has_value());
}

std::optional<uint64_t> randomSeed() {
  if (!g_seed_set.load()) return std::nullopt;
  return g_seed.load();
}

// --- CallbacksState --------------------------------------------------------------------------

CallbacksState::CallbacksState(StateSpec spec, Callbacks callbacks)
    : State(withDefaultOutcome(std::move(spec))),
      callbacks_(std::move(callbacks)),
      succeeded_(indexIn(outcomes(), kSucceeded)) {
  for (const auto& entry : callbacks_) addOutputKey(entry.key);
  placeCallbacks(callbacks_, outputKeys());
}

std::string CallbacksState::execute(UserData& userdata) {
  runPlaced(callbacks_, userdata);
  return kSucceeded;
}

int CallbacksState::executeAt(UserData& userdata, std::string& other) {
  runPlaced(callbacks_, userdata);
  if (succeeded_ < 0) other = kSucceeded;
  return succeeded_;
}

// --- PrintUserdataState ----------------------------------------------------------------------

PrintUserdataState::PrintUserdataState(StateSpec spec, std::ostream* out)
    : State(withDefaultOutcome(std::move(spec))), out_(out != nullptr ? out : &std::cout) {}

std::string PrintUserdataState::execute(UserData& userdata) {
  std::string text;
  for (const std::string& key : inputKeys()) {
    text += "userdata." + key + ": " + userdata.at(key).str() + "\n";
  }
  std::lock_guard lock(printMutex());
  *out_ << text << std::flush;
  return kSucceeded;
}

// --- RandomOutcomeState ----------------------------------------------------------------------

RandomOutcomeState::RandomOutcomeState(StateSpec spec, Callbacks callbacks,
                                       std::optional<uint64_t> seed)
    : State(withDefaultOutcome(std::move(spec))), callbacks_(std::move(callbacks)), seed_(seed) {
  addOutputKey(kOutcomeKey);
  for (const auto& entry : callbacks_) addOutputKey(entry.key);
  placeCallbacks(callbacks_, outputKeys());
}

std::string RandomOutcomeState::execute(UserData& userdata) {
  runPlaced(callbacks_, userdata);
  if (!seeded_) {
    std::optional<uint64_t> global = randomSeed();
    rng_ = seed_    ? *seed_
           : global ? *global ^ hashPath(path())
                    : (uint64_t{std::random_device{}()} << 32) ^ std::random_device{}();
    seeded_ = true;
  }
  const std::string& outcome = outcomes()[splitMix64(rng_) % outcomes().size()];
  userdata.set(kOutcomeKey, outcome);
  return outcome;
}

// --- ConditionalOutcomeState -----------------------------------------------------------------

ConditionalOutcomeState::ConditionalOutcomeState(StateSpec spec, Callbacks callbacks)
    : State([&] {
        StateSpec declared{
            .outcomes = {}, .input_keys = spec.input_keys, .output_keys = spec.output_keys};
        for (const std::string& outcome : spec.outcomes) {
          if (outcome != kDefault) declared.outcomes.push_back(outcome);
        }
        declared.outcomes.push_back(kDefault);
        return declared;
      }()),
      callbacks_(std::move(callbacks)) {
  for (const std::string& outcome : outcomes()) {
    if (outcome == kDefault) continue;
    addInputKey(outcome);
    addOutputKey(outcome);
  }
  addOutputKey(kOutcomeKey);
  for (const auto& entry : callbacks_) addOutputKey(entry.key);
  placeCallbacks(callbacks_, outputKeys());
  for (std::size_t i = 0; i + 1 < outcomes().size(); ++i) {
    conditions_.push_back(static_cast<std::size_t>(indexIn(inputKeys(), outcomes()[i])));
  }
  outcome_key_ = static_cast<std::size_t>(indexIn(outputKeys(), kOutcomeKey));
  choices_.assign(outcomes().begin(), outcomes().end());
}

// As the template's class: a condition whose key is not set (no callback wrote it, nothing
// else set it) is skipped, and the choice, `default` included, is written to `outcome`.
std::string ConditionalOutcomeState::execute(UserData& userdata) {
  std::string other;
  return outcomes()[static_cast<std::size_t>(executeAt(userdata, other))];
}

int ConditionalOutcomeState::executeAt(UserData& userdata, std::string& /*other*/) {
  runPlaced(callbacks_, userdata);
  std::size_t chosen = conditions_.size();  // `default`, the last outcome
  for (std::size_t i = 0; i < conditions_.size(); ++i) {
    const Value* condition = userdata.findInput(conditions_[i]);
    if (condition != nullptr && condition->truthy()) {
      chosen = i;
      break;
    }
  }
  userdata.setOutput(outcome_key_, choices_[chosen]);
  return static_cast<int>(chosen);
}

// --- LogState --------------------------------------------------------------------------------

LogState::LogState(std::string text, StateSpec spec, std::ostream* out)
    : State(withDefaultOutcome(std::move(spec), "done")),
      text_(std::move(text)),
      out_(out != nullptr ? out : &std::cout) {}

std::string LogState::execute(UserData& /*userdata*/) {
  std::lock_guard lock(printMutex());
  *out_ << text_ << "\n" << std::flush;
  return outcomes().front();
}

// --- SleepState ------------------------------------------------------------------------------

SleepState::SleepState(double seconds, StateSpec spec)
    : State(withDefaultOutcome(std::move(spec))), seconds_(seconds) {}

std::string SleepState::execute(UserData& /*userdata*/) {
  if (!(seconds_ >= 0)) {  // also NaN
    throw Error("SleepState " + backticked(displayName()) +
                ": the time to sleep must be 0 seconds or more, not " + std::to_string(seconds_));
  }
  std::chrono::duration<double> time(seconds_);
  if (!hasOutcome(kPreempted)) {
    if (time.count() > 0) ChildWorkers::aboutToBlock();
    std::this_thread::sleep_for(std::min(time, std::chrono::duration<double>(1e8)));
    return kSucceeded;
  }
  if (waitForPreempt(time)) {
    servicePreempt();
    return std::string(kPreempted);
  }
  return kSucceeded;
}

}  // namespace smachac::runtime
