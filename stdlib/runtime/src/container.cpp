// Container: children, the userdata scope and its key copying, checks common to both kinds,
// and runChild(), where every child executes.
#include "smachac/runtime/container.h"

#include <set>

#include "smachac/runtime/errors.h"
#include "text.h"

namespace smachac::runtime {

Container::Child::Child(std::string label_in, std::unique_ptr<State> state_in,
                        Remapping remapping_in, UserDataStore& store)
    : label(std::move(label_in)),
      state(std::move(state_in)),
      remapping(std::move(remapping_in)),
      view(store, *state, &remapping) {}

Container::Container(StateSpec spec, Map userdata)
    : State(std::move(spec)), userdata_(std::move(userdata)) {}

std::vector<std::string> Container::labels() const {
  std::vector<std::string> out;
  for (const Child& child : children_) out.push_back(child.label);
  return out;
}

int Container::indexOf(std::string_view label) const {
  for (std::size_t i = 0; i < children_.size(); ++i) {
    if (children_[i].label == label) return static_cast<int>(i);
  }
  return -1;
}

State& Container::child(std::string_view label) {
  int index = indexOf(label);
  if (index < 0) throw Error(kindAndName() + " has no state " + backticked(label));
  return *children_[static_cast<std::size_t>(index)].state;
}

Container::Child& Container::addChild(std::string label, std::unique_ptr<State> state,
                                      Remapping remapping) {
  if (state == nullptr) throw Error(kindAndName() + ": state " + backticked(label) + " is null");
  Child& child =
      children_.emplace_back(std::move(label), std::move(state), std::move(remapping), userdata_);
  assignPath(*child.state, childPath(child.label));
  assignObservers(*child.state, observers());
  invalidate();
  return child;
}

std::string Container::childPath(const std::string& label) const {
  return path().empty() ? label : path() + "/" + label;
}

void Container::propagatePath(const std::string& path) {
  State::propagatePath(path);
  for (Child& child : children_) assignPath(*child.state, childPath(child.label));
}

void Container::propagateObservers(const Observers& observers) {
  State::propagateObservers(observers);
  for (Child& child : children_) {
    child.view.trackWrites(false);  // runTraced() turns it on
    assignObservers(*child.state, observers);
  }
}

void Container::ensureChecked() {
  if (!checked_) checkConsistency();
}

bool Container::collectProblems(std::vector<std::string>& problems) {
  std::size_t before = problems.size();
  collectCommonProblems(problems);
  collectOwnProblems(problems);
  for (Child& child : children_) collectProblemsOf(*child.state, problems);
  checked_ = problems.size() == before;
  return checked_;
}

void Container::collectCommonProblems(std::vector<std::string>& problems) const {
  if (children_.empty()) problems.push_back(kindAndName() + " has no states");
  std::set<std::string_view> seen;
  for (const Child& child : children_) {
    if (!seen.insert(child.label).second) {
      problems.push_back(kindAndName() + " has two states labelled " + backticked(child.label));
    }
  }
}

int Container::runChild(Child& child, std::string& other) {
  if (traceSink() != nullptr) return runTraced(child, other);
  try {
    return child.state->executeAt(child.view, other);
  } catch (...) {
    failedChild(*child.state);
  }
}

int Container::runTraced(Child& child, std::string& other) {
  TraceSink& sink = *traceSink();
  State& state = *child.state;
  child.view.trackWrites(true);
  sink.write({.kind = TraceKind::Enter, .state = state.path()});
  int position = -1;
  try {
    position = state.executeAt(child.view, other);
  } catch (...) {
    failedChild(state);
  }
  sink.write(
      {.kind = TraceKind::Exit,
       .state = state.path(),
       .outcome = position >= 0 ? state.outcomes()[static_cast<std::size_t>(position)] : other,
       .written = &child.view.written()});
  return position;
}

void Container::failedChild(const State& state) const {
  try {
    throw;
  } catch (const ExecutionError&) {
    throw;
  } catch (const ConsistencyError&) {
    throw;
  } catch (const Error& e) {
    fail(state, e.what());
  } catch (const std::exception& e) {
    fail(state, "state " + backticked(state.displayName()) + " failed: " + e.what());
  } catch (...) {
    fail(state, "state " + backticked(state.displayName()) + " failed: unknown exception");
  }
}

void Container::fail(const State& who, const std::string& message) const {
  emit({.kind = TraceKind::Error, .state = who.path(), .message = message});
  throw ExecutionError(message);
}

void Container::copyInputKeys(UserData& parent) {
  const Keys& keys = inputKeys();
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (const Value* value = parent.findInput(i)) userdata_.set(keys[i], *value);
  }
}

void Container::copyOutputKeys(UserData& parent) {
  const Keys& keys = outputKeys();
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (std::optional<Value> value = userdata_.find(keys[i])) {
      parent.setOutput(i, std::move(*value));
    }
  }
}

std::string Container::finishPreempted() {
  servicePreempt();
  return std::string(kPreempted);
}

void Container::emit(TraceEvent event) const {
  if (TraceSink* sink = traceSink()) sink->write(event);
}

}  // namespace smachac::runtime
