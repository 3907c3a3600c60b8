// Concurrence: checks of the outcome policy, the split (threads) and join, and the outcome.
//
// Synchronisation: mutex_ guards the current run (child outcomes, errors, the decided entry);
// a child that returns records its outcome under it and, when the outcome map decides or the
// termination callback asks, preempts the children still running while holding it, so
// requestPreempt() from outside and early exits never race. callback_mutex_ serialises
// child_termination_cb, which runs without mutex_ held (it may preempt the container).
#include "smachac/runtime/concurrence.h"

#include "child_workers.h"
#include "smachac/runtime/errors.h"
#include "smachac/runtime/thread_observer.h"
#include "text.h"

namespace smachac::runtime {

namespace {

std::string describe(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown exception";
  }
}

}  // namespace

struct Concurrence::Run {
  std::vector<std::optional<std::string>> outcomes;  ///< per child, once it returned
  std::vector<uint8_t> done;                         ///< per child: returned or threw
  std::vector<std::exception_ptr> errors;            ///< per child
  std::optional<int> decided;                        ///< entries_ index, first to decide
  bool active = false;
};

CStringConcurrenceSpec::operator ConcurrenceSpec() const {
  // Through StateSpec's conversion: the keys' C strings read the same way.
  StateSpec keys =
      CStringSpec{.outcomes = outcomes, .input_keys = input_keys, .output_keys = output_keys};
  ConcurrenceSpec spec{.outcomes = std::move(keys.outcomes),
                       .default_outcome = std::string(cStringText(default_outcome)),
                       .outcome_map = {},
                       .input_keys = std::move(keys.input_keys),
                       .output_keys = std::move(keys.output_keys),
                       .early_exit = early_exit};
  for (const Entry& entry : outcome_map) {
    // The first of equal outcomes wins, as in OutcomeMap's initializer list.
    auto children = cStringMap(entry.children);
    spec.outcome_map.try_emplace(std::string(cStringText(entry.outcome)), children.begin(),
                                 children.end());
  }
  return spec;
}

Concurrence::Concurrence(ConcurrenceSpec spec)
    : Container({.outcomes = std::move(spec.outcomes),
                 .input_keys = std::move(spec.input_keys),
                 .output_keys = std::move(spec.output_keys)},
                std::move(spec.userdata)),
      spec_(std::move(spec)),
      run_(std::make_unique<Run>()),
      workers_(std::make_unique<ChildWorkers>()) {}

Concurrence::~Concurrence() = default;

std::string Concurrence::kindAndName() const { return "concurrence " + backticked(displayName()); }

void Concurrence::addState(std::string label, std::unique_ptr<State> state, Remapping remapping) {
  addChild(std::move(label), std::move(state), std::move(remapping));
}

void Concurrence::addState(std::string_view label, std::unique_ptr<State> state,
                           PairsLiteral remapping) {
  addChild(std::string(label), std::move(state), toMap(remapping));
}

void Concurrence::addState(const char* label, std::unique_ptr<State> state,
                           CStringPairs remapping) {
  addChild(std::string(cStringText(label)), std::move(state), cStringMap(remapping));
}

// --- checks ----------------------------------------------------------------------------------

void Concurrence::collectOwnProblems(std::vector<std::string>& problems) {
  std::string who = kindAndName() + ": ";
  if (spec_.default_outcome.empty()) {
    problems.push_back(kindAndName() + " has no default outcome");
  } else if (!hasOutcome(spec_.default_outcome)) {
    problems.push_back(who + "default outcome " + backticked(spec_.default_outcome) +
                       " is not one of its outcomes");
  }
  entries_.clear();
  for (const auto& [outcome, needs] : spec_.outcome_map) {
    std::string entry = who + "outcome map entry " + backticked(outcome);
    if (!hasOutcome(outcome)) problems.push_back(entry + " is not one of its outcomes");
    Entry resolved{.outcome = indexIn(outcomes(), outcome), .need = {}};
    for (const auto& [label, child_outcome] : needs) {
      int child = indexOf(label);
      if (child < 0) {
        problems.push_back(entry + " names " + backticked(label) +
                           ", which is not one of its states");
        continue;
      }
      const State& state = *children()[static_cast<std::size_t>(child)].state;
      if (!state.hasOutcome(child_outcome) && child_outcome != kPreempted) {
        problems.push_back(entry + " expects outcome " + backticked(child_outcome) + " of " +
                           backticked(label) + ", which is not one of its outcomes");
      }
      resolved.need.emplace_back(child, child_outcome);
    }
    entries_.push_back(std::move(resolved));
  }
}

// --- split and join --------------------------------------------------------------------------

std::string Concurrence::execute(UserData& parent) {
  ensureChecked();
  copyInputKeys(parent);
  begin();
  runAll();
  std::string outcome = finish();
  copyOutputKeys(parent);
  return outcome;
}

void Concurrence::begin() {
  std::lock_guard lock(mutex_);
  std::size_t n = children().size();
  run_->outcomes.assign(n, std::nullopt);
  run_->done.assign(n, 0);
  run_->errors.assign(n, nullptr);
  run_->decided.reset();
  run_->active = true;
  // Asked before it started: every child starts preempted (SMACH would let them run on).
  if (preemptRequested()) preemptRunningLocked();
}

void Concurrence::runAll() {
  ThreadObserver* observer = threadObserver();
  const std::size_t n = children().size();
  if (observer != nullptr) observer->split(n);
  try {
    workers_->run(n, [this](std::size_t i) { runOne(i); });
  } catch (...) {
    // No worker could be started: no child ran, each has returned at once.
    for (std::size_t i = 0; observer != nullptr && i < n; ++i) observer->returned();
    if (observer != nullptr) observer->joined();
    throw;
  }
  if (observer != nullptr) observer->joined();
}

std::size_t Concurrence::threadWakes() const { return workers_->wakes(); }

void Concurrence::runOne(std::size_t index) {
  try {
    Child& child = children()[index];
    std::string outcome;
    int position = runChild(child, outcome);
    if (position >= 0) outcome = child.state->outcomes()[static_cast<std::size_t>(position)];
    childDone(index, std::move(outcome), nullptr);
  } catch (...) {
    childDone(index, std::nullopt, std::current_exception());
  }
  if (ThreadObserver* observer = threadObserver()) observer->returned();
}

void Concurrence::childDone(std::size_t index, std::optional<std::string> outcome,
                            std::exception_ptr error) {
  if (!spec_.child_termination_cb) {
    std::lock_guard lock(mutex_);
    recordLocked(index, std::move(outcome), error);
    return settleLocked(error != nullptr);
  }
  std::lock_guard callback_lock(callback_mutex_);
  ChildOutcomes snapshot;
  {
    std::lock_guard lock(mutex_);
    recordLocked(index, std::move(outcome), error);
    if (error) return settleLocked(true);
    snapshot = snapshotLocked();
  }
  bool preempt_others = false;
  try {
    preempt_others = spec_.child_termination_cb(snapshot);
  } catch (...) {
    error = std::make_exception_ptr(ExecutionError(
        kindAndName() +
        ": child termination callback failed: " + describe(std::current_exception())));
  }
  std::lock_guard lock(mutex_);
  if (error) run_->errors[index] = error;
  settleLocked(preempt_others || error != nullptr);
}

void Concurrence::recordLocked(std::size_t index, std::optional<std::string> outcome,
                               std::exception_ptr error) {
  run_->outcomes[index] = std::move(outcome);
  run_->errors[index] = std::move(error);
  run_->done[index] = 1;
}

void Concurrence::settleLocked(bool preempt_others) {
  if (!preempt_others && spec_.early_exit && !run_->decided) {
    run_->decided = decideLocked(false);
    preempt_others = run_->decided.has_value();
  }
  if (preempt_others) preemptRunningLocked();
}

void Concurrence::preemptRunningLocked() {
  for (std::size_t i = 0; i < children().size(); ++i) {
    if (!run_->done[i]) children()[i].state->requestPreempt();
  }
}

void Concurrence::requestPreempt() {
  std::lock_guard lock(mutex_);
  State::requestPreempt();
  if (run_->active) preemptRunningLocked();
}

std::string Concurrence::finish() {
  std::unique_lock lock(mutex_);
  run_->active = false;
  bool children_serviced = true;
  for (Child& child : children()) {
    if (!child.state->preemptRequested()) continue;
    children_serviced = false;
    child.state->recallPreempt();
  }
  for (const std::exception_ptr& error : run_->errors) {
    if (error) std::rethrow_exception(error);
  }
  if (preemptRequested() && children_serviced) {
    lock.unlock();
    return finishPreempted();
  }
  // Only outcome_cb reads the outcomes by label: no map of them built per run without one.
  ChildOutcomes outcomes = spec_.outcome_cb ? snapshotLocked() : ChildOutcomes{};
  std::optional<int> entry = run_->decided ? run_->decided : decideLocked(true);
  lock.unlock();
  return chooseOutcome(outcomes, entry);
}

// --- the outcome -----------------------------------------------------------------------------

ChildOutcomes Concurrence::snapshotLocked() const {
  ChildOutcomes out;
  for (std::size_t i = 0; i < children().size(); ++i) {
    if (run_->outcomes[i]) out.emplace(children()[i].label, *run_->outcomes[i]);
  }
  return out;
}

bool Concurrence::satisfied(const Entry& entry) const {
  for (const auto& [child, outcome] : entry.need) {
    const auto& actual = run_->outcomes[static_cast<std::size_t>(child)];
    if (!actual || *actual != outcome) return false;
  }
  return true;
}

bool Concurrence::possible(const Entry& entry) const {
  for (const auto& [child, outcome] : entry.need) {
    auto index = static_cast<std::size_t>(child);
    if (run_->done[index] && run_->outcomes[index] != outcome) return false;
  }
  return true;
}

// The outcome_map rule of the runtime README ("Choosing among outcome_map entries"): more
// conditions win, then the earlier entry in map order.
bool Concurrence::outranks(int a, int b) const {
  std::size_t need_a = entries_[static_cast<std::size_t>(a)].need.size();
  std::size_t need_b = entries_[static_cast<std::size_t>(b)].need.size();
  return need_a != need_b ? need_a > need_b : a < b;
}

bool Concurrence::choosable(const Entry& entry) const {
  return !entry.need.empty() && satisfied(entry);
}

std::optional<int> Concurrence::decideLocked(bool final) const {
  std::optional<int> best;
  for (int k = 0; k < static_cast<int>(entries_.size()); ++k) {
    if (choosable(entries_[static_cast<std::size_t>(k)]) && (!best || outranks(k, *best))) best = k;
  }
  if (!best || final) return best;
  for (int k = 0; k < static_cast<int>(entries_.size()); ++k) {
    const Entry& entry = entries_[static_cast<std::size_t>(k)];
    if (outranks(k, *best) && !satisfied(entry) && possible(entry)) return std::nullopt;
  }
  return best;
}

std::string Concurrence::chooseOutcome(const ChildOutcomes& outcomes_so_far,
                                       std::optional<int> entry) {
  if (spec_.outcome_cb) {
    std::string chosen;
    try {
      chosen = spec_.outcome_cb(outcomes_so_far);
    } catch (...) {
      fail(*this,
           kindAndName() + ": outcome callback failed: " + describe(std::current_exception()));
    }
    if (!chosen.empty() && !hasOutcome(chosen)) {
      fail(*this, kindAndName() + ": outcome callback returned " + backticked(chosen) +
                      ", which is not one of its outcomes");
    }
    if (!chosen.empty()) return chosen;
  }
  if (entry) return outcomes()[static_cast<std::size_t>(entries_[*entry].outcome)];
  return spec_.default_outcome;
}

}  // namespace smachac::runtime
