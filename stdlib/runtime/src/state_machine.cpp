// StateMachine: the consistency check that resolves transitions to indices, and the run loop.
//
// Preemption follows SMACH 2.5's StateMachine (README.md, "Preemption"): a request sets the
// machine's flag and is passed to the current child. The child's outcome is followed as
// usual. Before the next child starts, a request the last child serviced (its flag is clear)
// is done with; one it ignored is taken back from it and passed on to the next child. At a
// terminal outcome the machine services its own request when its last child did. mutex_
// guards preempted_ against requestPreempt() from other threads.
//
// Entering a child takes no lock while no request is pending: the machine publishes current_
// and then reads its request flag, requestPreempt() sets the flag and then reads current_,
// all four sequentially consistent. So at least one of them sees the other: either the
// requester preempts the new child, or the machine sees the request and handles it under
// mutex_ (preemptCurrentLocked() does nothing the second time for the same child).
#include "smachac/runtime/state_machine.h"

#include <mutex>

#include "smachac/runtime/errors.h"
#include "text.h"

namespace smachac::runtime {

StateMachine::StateMachine(StateMachineSpec spec)
    : Container({.outcomes = std::move(spec.outcomes),
                 .input_keys = std::move(spec.input_keys),
                 .output_keys = std::move(spec.output_keys)},
                std::move(spec.userdata)) {
  userdata().setShared(false);  // its children run one at a time
}

std::string StateMachine::kindAndName() const {
  return "state machine " + backticked(displayName());
}

void StateMachine::addState(std::string label, std::unique_ptr<State> state,
                            Transitions transitions, Remapping remapping) {
  addChild(std::move(label), std::move(state), std::move(remapping));
  transitions_.push_back(std::move(transitions));
}

void StateMachine::addState(std::string_view label, std::unique_ptr<State> state,
                            PairsLiteral transitions, PairsLiteral remapping) {
  addState(std::string(label), std::move(state), toMap(transitions), toMap(remapping));
}

void StateMachine::addState(const char* label, std::unique_ptr<State> state,
                            CStringPairs transitions, CStringPairs remapping) {
  addState(std::string(cStringText(label)), std::move(state), cStringMap(transitions),
           cStringMap(remapping));
}

void StateMachine::collectOwnProblems(std::vector<std::string>& problems) {
  steps_.clear();
  for (Child& child : children()) steps_.push_back({.child = &child, .targets = {}});
  for (std::size_t i = 0; i < children().size(); ++i) resolveChild(i, problems);
}

void StateMachine::resolveChild(std::size_t index, std::vector<std::string>& problems) {
  const State& state = *children()[index].state;
  const Transitions& transitions = transitions_[index];
  std::string who = "state " + backticked(state.displayName()) + ": ";
  for (const auto& [outcome, target] : transitions) {
    if (!state.hasOutcome(outcome)) {
      problems.push_back(who + "transition from " + backticked(outcome) +
                         ", which is not one of its outcomes");
    }
  }
  for (const std::string& outcome : state.outcomes()) {
    auto it = transitions.find(outcome);
    bool explicit_target = it != transitions.end() && !it->second.empty();
    const std::string& target = explicit_target ? it->second : outcome;
    int child = explicit_target ? indexOf(target) : -1;
    int own = indexIn(outcomes(), target);
    if (child >= 0) {
      steps_[index].targets.push_back(child);
    } else if (own >= 0) {
      steps_[index].targets.push_back(~own);
    } else if (explicit_target) {
      problems.push_back(who + "outcome " + backticked(outcome) + " goes to " + backticked(target) +
                         ", which is neither a state nor an outcome of " + kindAndName());
    } else {
      problems.push_back(who + "outcome " + backticked(outcome) +
                         " has no transition and is not an outcome of " + kindAndName());
    }
  }
}

std::string StateMachine::execute(UserData& parent) {
  ensureChecked();
  copyInputKeys(parent);
  std::string outcome = runFrom(0);
  copyOutputKeys(parent);
  return outcome;
}

std::string StateMachine::runFrom(std::size_t index) {
  for (;;) {
    const Step& step = steps_[index];
    enterChild(static_cast<int>(index));
    int position = -1;
    try {
      position = runChild(*step.child, other_);
    } catch (...) {
      finishRun(index);
      throw;
    }
    if (position < 0) undeclaredOutcome(index);
    Target target = step.targets[static_cast<std::size_t>(position)];
    emitTransition(index, position, target);
    if (target < 0) {
      finishRun(index);
      return outcomes()[static_cast<std::size_t>(~target)];
    }
    index = static_cast<std::size_t>(target);
  }
}

void StateMachine::enterChild(int index) {
  current_.store(index);
  if (preemptRequested()) enterPreempted();
}

void StateMachine::enterPreempted() {
  std::lock_guard lock(mutex_);
  if (preempted_ >= 0 && !childAt(preempted_).preemptRequested()) {
    State::servicePreempt();  // the last preempted child serviced the request
    preempted_ = -1;
  } else {
    preemptCurrentLocked();  // not yet passed to a child, or ignored by the last one
  }
}

void StateMachine::finishRun(std::size_t last) {
  std::lock_guard lock(mutex_);
  if (preemptRequested() && preempted_ >= 0 && !children()[last].state->preemptRequested()) {
    State::servicePreempt();
  }
  // A request the last preempted child ignored must not preempt it on the next run.
  if (preempted_ >= 0) childAt(preempted_).recallPreempt();
  preempted_ = -1;
  current_ = -1;
}

void StateMachine::requestPreempt() {
  std::lock_guard lock(mutex_);
  State::requestPreempt();
  if (current_.load() >= 0) preemptCurrentLocked();
}

void StateMachine::preemptCurrentLocked() {
  int current = current_.load();
  if (current < 0 || preempted_ == current) return;
  if (preempted_ >= 0) childAt(preempted_).recallPreempt();
  preempted_ = current;
  childAt(current).requestPreempt();
}

State& StateMachine::childAt(int index) {
  return *children()[static_cast<std::size_t>(index)].state;
}

void StateMachine::undeclaredOutcome(std::size_t index) const {
  const State& state = *children()[index].state;
  fail(state, "state " + backticked(state.displayName()) + " returned outcome " +
                  backticked(other_) + ", which is not one of its outcomes");
}

void StateMachine::emitTransition(std::size_t index, int position, Target target) const {
  if (traceSink() == nullptr) return;
  const State& state = *children()[index].state;
  bool terminal = target < 0;
  const std::string& to = terminal ? outcomes()[static_cast<std::size_t>(~target)]
                                   : children()[static_cast<std::size_t>(target)].label;
  emit({.kind = TraceKind::Transition,
        .state = state.path(),
        .outcome = state.outcomes()[static_cast<std::size_t>(position)],
        .target = to,
        .terminal = terminal});
}

}  // namespace smachac::runtime
