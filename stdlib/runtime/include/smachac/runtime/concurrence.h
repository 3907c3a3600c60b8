// Concurrence: SMACH's split-join container. Every child runs at once as far as they block
// (taken in order by the calling thread; a child that blocks or runs long hands the children
// not yet started to threads of their own); the container returns when all have returned.
// Its outcome, in SMACH's documented precedence:
//
//   1. outcome_cb(child outcomes), when given and it returns a non-empty outcome;
//   2. the outcome_map entry that decided first (see below);
//   3. the best outcome_map entry satisfied by the final child outcomes;
//   4. default_outcome.
//
// An entry {container_outcome: {child: outcome, ...}} is satisfied when every child it names
// returned that outcome. Among satisfied entries, the one with the most conditions wins, then
// the first in map order; an entry without conditions is never chosen (SMACH 2.5's rule, see
// "Choosing among outcome_map entries" in the runtime's README.md).
// With early_exit (the default), an entry decides as soon as it is satisfied and no entry that
// could still be satisfied ranks above it: the children still running are preempted.
// child_termination_cb runs after each child returns; returning true preempts the others.
// A preempt request on the container reaches every running child; once all have returned it
// returns `preempted` if none ignored the request, else its usual outcome (SMACH 2.5).
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "smachac/runtime/container.h"
#include "smachac/runtime/light_mutex.h"
#include "smachac/runtime/literals.h"

namespace smachac::runtime {

class ChildWorkers;

/// container outcome -> {child label -> child outcome}
using OutcomeMap = std::map<std::string, std::map<std::string, std::string>>;
/// child label -> outcome, for the children that have returned so far.
using ChildOutcomes = std::map<std::string, std::string>;

struct ConcurrenceSpec {
  Keys outcomes{};
  std::string default_outcome{};
  OutcomeMap outcome_map{};
  Keys input_keys{};
  Keys output_keys{};
  Map userdata{};
  /// After each child returns; true preempts the children still running.
  std::function<bool(const ChildOutcomes&)> child_termination_cb{};
  /// After all returned; a non-empty result is the container's outcome.
  std::function<std::string(const ChildOutcomes&)> outcome_cb{};
  /// Preempt the remaining children once an outcome_map entry has decided.
  bool early_exit = true;
};

/// ConcurrenceSpec's literal form, what generated code writes (C strings, nothing to destroy;
/// see literals.h): `{.outcomes = {"ok"}, .default_outcome = "ok", .outcome_map = {{"ok",
/// {{"CHILD", "succeeded"}}}}, .early_exit = false}`. No callbacks and no userdata.
struct CStringConcurrenceSpec {
  /// A container outcome and the child outcomes it needs.
  struct Entry {
    const char* outcome;
    CStringPairs children;
  };
  std::initializer_list<const char*> outcomes{};
  const char* default_outcome = "";
  std::initializer_list<Entry> outcome_map{};
  std::initializer_list<const char*> input_keys{};
  std::initializer_list<const char*> output_keys{};
  bool early_exit = true;

  /// Implicit, so that emplace<Concurrence> can be given one.
  operator ConcurrenceSpec() const;
};

class Concurrence : public Container {
 public:
  explicit Concurrence(ConcurrenceSpec spec);
  ~Concurrence() override;

  /// Adds a child; returns it (typed). Remapping as a literal: `{{"x", "parent_x"}}`.
  template <std::derived_from<State> T>
  T& add(std::string_view label, std::unique_ptr<T> state, PairsLiteral remapping = {}) {
    T* added = state.get();  // addState rejects a null state before it is dereferenced
    addState(label, std::move(state), remapping);
    return *added;
  }
  /// Constructs a child from `args` and adds it (StateMachine::emplace without transitions).
  template <std::derived_from<State> T, class... Args>
  T& emplace(const char* label, CStringPairs remapping, Args&&... args) {
    T* added = new T(std::forward<Args>(args)...);
    addState(label, std::unique_ptr<State>(added), remapping);
    return *added;
  }
  /// The same with a remapping built at run time.
  template <std::derived_from<State> T>
  T& add(std::string_view label, std::unique_ptr<T> state, Remapping remapping) {
    T* added = state.get();
    addState(std::string(label), std::move(state), std::move(remapping));
    return *added;
  }

  std::string execute(UserData& parent) override;
  void requestPreempt() override;

  /// How many times its kept threads were woken to take a child, over every execution so far:
  /// a child that blocks or runs long wakes them, quick children none (for tests).
  std::size_t threadWakes() const;

 protected:
  void collectOwnProblems(std::vector<std::string>& problems) override;
  std::string kindAndName() const override;

 private:
  struct Entry {
    int outcome = 0;                                ///< index in outcomes()
    std::vector<std::pair<int, std::string>> need;  ///< child index, outcome
  };
  struct Run;

  void addState(std::string label, std::unique_ptr<State> state, Remapping remapping);
  void addState(std::string_view label, std::unique_ptr<State> state, PairsLiteral remapping);
  void addState(const char* label, std::unique_ptr<State> state, CStringPairs remapping);
  void begin();
  void runAll();
  void runOne(std::size_t index);
  void childDone(std::size_t index, std::optional<std::string> outcome, std::exception_ptr error);
  /// Notes what child `index` returned (or threw).
  void recordLocked(std::size_t index, std::optional<std::string> outcome,
                    std::exception_ptr error);
  void settleLocked(bool preempt_others);
  void preemptRunningLocked();
  std::string finish();
  ChildOutcomes snapshotLocked() const;
  bool satisfied(const Entry& entry) const;
  bool possible(const Entry& entry) const;
  bool choosable(const Entry& entry) const;  ///< has conditions and all hold
  bool outranks(int a, int b) const;
  std::optional<int> decideLocked(bool final) const;
  std::string chooseOutcome(const ChildOutcomes& outcomes_so_far, std::optional<int> entry);

  ConcurrenceSpec spec_;
  std::vector<Entry> entries_;             ///< resolved outcome_map, in map order
  std::mutex callback_mutex_;              ///< serialises child_termination_cb
  LightMutex mutex_;                       ///< guards run_ (taken for every child that returns)
  std::unique_ptr<Run> run_;               ///< state of the current execution
  std::unique_ptr<ChildWorkers> workers_;  ///< the children's threads, kept between executions
};

}  // namespace smachac::runtime
