// Container: what StateMachine and Concurrence share. A container owns its children and a
// userdata scope (initialised at construction, kept across runs, as SMACH's container
// userdata). On entry it copies its declared input keys from the parent's view into the
// scope, on exit its declared output keys back (keys that are not set are skipped).
//
// runChild() is the one place a child executes: it emits enter/exit (and error) trace events
// and turns whatever the child throws into an ExecutionError naming the child.
#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "smachac/runtime/state.h"
#include "smachac/runtime/trace.h"
#include "smachac/runtime/userdata.h"

namespace smachac::runtime {

class Container : public State {
 public:
  /// The container's own userdata (the scope its children read and write).
  UserDataStore& userdata() { return userdata_; }
  const UserDataStore& userdata() const { return userdata_; }

  std::size_t size() const { return children_.size(); }
  /// Labels in the order the children were added.
  std::vector<std::string> labels() const;
  /// The child called `label`; throws Error when there is none.
  State& child(std::string_view label);

 protected:
  struct Child {
    Child(std::string label_in, std::unique_ptr<State> state_in, Remapping remapping_in,
          UserDataStore& store);
    std::string label;
    std::unique_ptr<State> state;
    Remapping remapping;
    UserData view;  ///< over the container's scope, through `remapping`
  };

  Container(StateSpec spec, Map userdata);

  Child& addChild(std::string label, std::unique_ptr<State> state, Remapping remapping);
  std::deque<Child>& children() { return children_; }
  const std::deque<Child>& children() const { return children_; }
  int indexOf(std::string_view label) const;

  /// Checks once before the first run (and again after a change).
  void ensureChecked();
  /// Container-specific checks (called with the common ones already done).
  virtual void collectOwnProblems(std::vector<std::string>& problems) = 0;
  void invalidate() { checked_ = false; }

  /// The child's outcome as its position in the child's outcomes(); -1 for one that is not
  /// there, in `other`.
  int runChild(Child& child, std::string& other);
  void copyInputKeys(UserData& parent);
  void copyOutputKeys(UserData& parent);
  /// Services this container's preempt request and returns `preempted`.
  std::string finishPreempted();

  void emit(TraceEvent event) const;
  /// Emits an error event for `who` and throws ExecutionError(message).
  [[noreturn]] void fail(const State& who, const std::string& message) const;
  /// "state machine `SM`" / "concurrence `C`", for messages.
  virtual std::string kindAndName() const = 0;

  bool collectProblems(std::vector<std::string>& problems) final;
  void propagateObservers(const Observers& observers) final;
  void propagatePath(const std::string& path) final;

 private:
  std::string childPath(const std::string& label) const;
  /// runChild() with a trace sink: enter and exit events, the keys the child wrote.
  int runTraced(Child& child, std::string& other);
  /// In a handler: rethrows what `state` threw as an ExecutionError naming it (see fail()).
  [[noreturn]] void failedChild(const State& state) const;
  void collectCommonProblems(std::vector<std::string>& problems) const;

  UserDataStore userdata_;
  std::deque<Child> children_;
  bool checked_ = false;
};

}  // namespace smachac::runtime
