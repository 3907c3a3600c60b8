// StateMachine: SMACH's sequential container. The first state added is the initial one; each
// outcome of a child goes where its transition says: a sibling label or an outcome of the
// machine. An outcome without a transition falls through to the machine's outcome of the same
// name (SMACH's implicit terminal transition); a label wins over a machine outcome.
//
// Before the first run the machine is checked (as SMACH's check_consistency, recursively) and
// its transitions are resolved to indices, so a transition costs no string map lookup.
#pragma once

#include <atomic>
#include <concepts>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "smachac/runtime/container.h"
#include "smachac/runtime/light_mutex.h"
#include "smachac/runtime/literals.h"

namespace smachac::runtime {

/// Outcome -> sibling label or container outcome ("" also means the container outcome).
using Transitions = std::map<std::string, std::string, std::less<>>;

struct StateMachineSpec {
  Keys outcomes{};
  Keys input_keys{};
  Keys output_keys{};
  /// Initial userdata of the machine's scope (the script's `userdata:`).
  Map userdata{};
};

class StateMachine : public Container {
 public:
  explicit StateMachine(StateMachineSpec spec);

  /// Adds a child; returns it (typed) so generated code can fill a nested container after.
  /// Transitions and remapping as literals: `{{"succeeded", "NEXT"}}`.
  template <std::derived_from<State> T>
  T& add(std::string_view label, std::unique_ptr<T> state, PairsLiteral transitions = {},
         PairsLiteral remapping = {}) {
    T* added = state.get();  // addState rejects a null state before it is dereferenced
    addState(label, std::move(state), transitions, remapping);
    return *added;
  }
  /// Constructs a child from `args` (`T(args...)`) and adds it: what generated code writes,
  /// `sm.emplace<rt::LogState>("SAY", {{"done", "NEXT"}}, {}, "hi", rt::CStringSpec{})`. The
  /// label, transitions and remapping are C strings (string literals: nothing to construct at
  /// the call), and the state is made inside this template, which every statement of the same
  /// state class and argument types shares: a statement compiles to the call alone, where
  /// add()'s unique_ptr argument costs each statement its construction and clean-up.
  template <std::derived_from<State> T, class... Args>
  T& emplace(const char* label, CStringPairs transitions, CStringPairs remapping, Args&&... args) {
    T* added = new T(std::forward<Args>(args)...);
    addState(label, std::unique_ptr<State>(added), transitions, remapping);
    return *added;
  }
  /// The same with transitions (and remapping) built at run time.
  template <std::derived_from<State> T>
  T& add(std::string_view label, std::unique_ptr<T> state, Transitions transitions,
         Remapping remapping = {}) {
    T* added = state.get();
    addState(std::string(label), std::move(state), std::move(transitions), std::move(remapping));
    return *added;
  }

  std::string execute(UserData& parent) override;
  void requestPreempt() override;

 protected:
  void collectOwnProblems(std::vector<std::string>& problems) override;
  std::string kindAndName() const override;

 private:
  /// Where an outcome leads: a child index (>= 0) or ~outcome index (< 0).
  using Target = int32_t;

  void addState(std::string label, std::unique_ptr<State> state, Transitions transitions,
                Remapping remapping);
  void addState(std::string_view label, std::unique_ptr<State> state, PairsLiteral transitions,
                PairsLiteral remapping);
  void addState(const char* label, std::unique_ptr<State> state, CStringPairs transitions,
                CStringPairs remapping);
  void resolveChild(std::size_t index, std::vector<std::string>& problems);
  std::string runFrom(std::size_t index);
  void enterChild(int index);
  /// enterChild() with a preempt request pending: passes it on, or takes it back (serviced).
  void enterPreempted();
  void finishRun(std::size_t last);
  void preemptCurrentLocked();
  State& childAt(int index);
  /// Fails for an undeclared outcome (position -1) of child `index`.
  [[noreturn]] void undeclaredOutcome(std::size_t index) const;
  void emitTransition(std::size_t index, int position, Target target) const;

  std::vector<Transitions> transitions_;  ///< per child, as added
  /// A child and where its outcomes lead, what a transition reads.
  struct Step {
    Child* child;
    std::vector<Target> targets;  ///< per declared outcome
  };
  std::vector<Step> steps_;       ///< per child, resolved by the check
  LightMutex mutex_;              ///< guards preempted_ and current_'s readers
  std::atomic<int> current_{-1};  ///< the child running or about to run, or -1
  int preempted_ = -1;            ///< the child last asked to preempt, or -1
  std::string other_;             ///< an undeclared outcome a child returned
};

}  // namespace smachac::runtime
