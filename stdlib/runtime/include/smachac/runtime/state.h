// State: the unit of a SMACH machine. A state declares its outcomes and the userdata keys it
// reads (input keys) and writes (output keys), and execute() returns one of its outcomes.
//
// Preemption is cooperative, as in SMACH: requestPreempt() (from any thread) sets a flag that
// the running state polls with preemptRequested() or sleeps on with waitForPreempt(); a state
// that honours it calls servicePreempt() and returns `preempted`. Containers forward requests
// to their running children and follow SMACH 2.5's rules for the rest (see README.md).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "smachac/runtime/literals.h"
#include "smachac/runtime/userdata.h"

namespace smachac::runtime {

/// The reserved outcome of a preempted state; any state may return it.
inline constexpr std::string_view kPreempted = "preempted";

/// What every state declares, written with designated initializers:
///   {.outcomes = {"succeeded", "aborted"}, .input_keys = {"x"}, .output_keys = {"y"}}
/// Generated code writes SpecLiteral (literals.h), which converts to it.
struct StateSpec {
  Keys outcomes{};
  Keys input_keys{};
  Keys output_keys{};
};

class TraceSink;
class ThreadObserver;

/// Who hears about a running machine: set on the root, shared by everything under it.
struct Observers {
  TraceSink* trace = nullptr;
  ThreadObserver* threads = nullptr;
};

class State {
 public:
  explicit State(StateSpec spec);
  virtual ~State();
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  /// Runs the state; returns one of outcomes() (or `preempted`).
  virtual std::string execute(UserData& userdata) = 0;
  /// What containers call: runs the state and returns the position of its outcome in
  /// outcomes(), or -1 for an outcome that is not one of them, which goes to `other`. By
  /// default execute() and a search; states that know the position override it.
  virtual int executeAt(UserData& userdata, std::string& other);

  const Keys& outcomes() const { return outcomes_; }
  const Keys& inputKeys() const { return input_keys_; }
  const Keys& outputKeys() const { return output_keys_; }
  bool hasOutcome(std::string_view outcome) const;
  bool declaresInput(std::string_view key) const;
  bool declaresOutput(std::string_view key) const;

  /// Labels from the root joined by '/', e.g. "SUB/FOO"; the root's path is empty.
  const std::string& path() const { return path_; }
  /// The path for messages: the root is shown as `root`.
  std::string displayName() const;

  /// Asks the state to stop soon. Thread-safe; containers forward it to running children.
  virtual void requestPreempt();
  /// Sequentially consistent (a plain load on x86 and ARM64): a state machine publishes its
  /// current child and then reads this flag without a lock (state_machine.cpp).
  bool preemptRequested() const { return preempt_.load(); }
  /// Clears the request: the state has acted on it.
  void servicePreempt();
  /// Clears a request the state did not act on (containers do this after a child returns).
  void recallPreempt() { servicePreempt(); }
  /// Sleeps up to `timeout`; returns true as soon as a preempt is requested (then the caller
  /// should servicePreempt() and return `preempted`), false when the time ran out. Before it
  /// sleeps, siblings in a Concurrence that wait to start get a thread at once.
  bool waitForPreempt(std::chrono::duration<double> timeout);

  /// Checks this state and everything under it; throws ConsistencyError listing every problem.
  void checkConsistency();

  /// Sends trace events of this state and everything under it to `sink` (nullptr: none).
  /// Attach before running.
  void setTraceSink(std::shared_ptr<TraceSink> sink);
  TraceSink* traceSink() const { return observers_.trace; }
  /// Tells `observer` (not owned; nullptr: none) how the Concurrences under this state split
  /// and join threads. Attach before running.
  void setThreadObserver(ThreadObserver* observer);
  ThreadObserver* threadObserver() const { return observers_.threads; }

 protected:
  /// For states whose keys follow from their arguments (callbacks add output keys).
  void addOutcome(const std::string& outcome);
  void addInputKey(const std::string& key);
  void addOutputKey(const std::string& key);

  /// Containers: append the problems of this state and its children; true when none.
  virtual bool collectProblems(std::vector<std::string>& problems);
  virtual void propagateObservers(const Observers& observers);
  const Observers& observers() const { return observers_; }
  virtual void propagatePath(const std::string& path);

  static bool collectProblemsOf(State& child, std::vector<std::string>& problems) {
    return child.collectProblems(problems);
  }
  static void assignObservers(State& child, const Observers& observers) {
    child.propagateObservers(observers);
  }
  static void assignPath(State& child, const std::string& path) { child.propagatePath(path); }

 private:
  Keys outcomes_;
  Keys input_keys_;
  Keys output_keys_;
  std::string path_;
  std::atomic<bool> preempt_{false};
  std::mutex wait_mutex_;
  std::condition_variable wait_cv_;
  Observers observers_;
  std::shared_ptr<TraceSink> owned_trace_;
};

}  // namespace smachac::runtime
