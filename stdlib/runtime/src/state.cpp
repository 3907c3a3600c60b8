// State: declared outcomes and keys, the preempt flag with its wake-up, path and observer wiring.
#include "smachac/runtime/state.h"

#include "child_workers.h"
#include "smachac/runtime/errors.h"
#include "smachac/runtime/trace.h"
#include "text.h"

namespace smachac::runtime {

namespace {

bool contains(const Keys& keys, std::string_view key) { return indexIn(keys, key) >= 0; }

void addUnique(Keys& keys, const std::string& key) {
  if (!contains(keys, key)) keys.push_back(key);
}

}  // namespace

State::State(StateSpec spec)
    : outcomes_(std::move(spec.outcomes)),
      input_keys_(std::move(spec.input_keys)),
      output_keys_(std::move(spec.output_keys)) {}

State::~State() = default;

bool State::hasOutcome(std::string_view outcome) const { return contains(outcomes_, outcome); }
bool State::declaresInput(std::string_view key) const { return contains(input_keys_, key); }
bool State::declaresOutput(std::string_view key) const { return contains(output_keys_, key); }

int State::executeAt(UserData& userdata, std::string& other) {
  other = execute(userdata);
  return indexIn(outcomes_, other);
}

std::string State::displayName() const { return path_.empty() ? "root" : path_; }

void State::requestPreempt() {
  {
    std::lock_guard lock(wait_mutex_);
    preempt_.store(true);  // sequentially consistent: see preemptRequested()
  }
  wait_cv_.notify_all();
  if (TraceSink* sink = traceSink()) sink->write({.kind = TraceKind::Preempt, .state = path_});
}

void State::servicePreempt() {
  std::lock_guard lock(wait_mutex_);
  preempt_.store(false, std::memory_order_release);
}

bool State::waitForPreempt(std::chrono::duration<double> timeout) {
  // Clamped so that "forever" (1e300 s) does not overflow the clock.
  std::chrono::duration<double> wait = std::min(timeout, std::chrono::duration<double>(1e8));
  auto deadline = std::chrono::steady_clock::now() +
                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(wait);
  if (wait.count() > 0 && !preemptRequested()) ChildWorkers::aboutToBlock();
  std::unique_lock lock(wait_mutex_);
  return wait_cv_.wait_until(lock, deadline, [this] { return preemptRequested(); });
}

void State::checkConsistency() {
  std::vector<std::string> problems;
  if (!collectProblems(problems)) throw ConsistencyError(std::move(problems));
}

void State::setTraceSink(std::shared_ptr<TraceSink> sink) {
  owned_trace_ = std::move(sink);
  Observers observers = observers_;
  observers.trace = owned_trace_.get();
  propagateObservers(observers);
}

void State::setThreadObserver(ThreadObserver* observer) {
  Observers observers = observers_;
  observers.threads = observer;
  propagateObservers(observers);
}

void State::addOutcome(const std::string& outcome) { addUnique(outcomes_, outcome); }
void State::addInputKey(const std::string& key) { addUnique(input_keys_, key); }
void State::addOutputKey(const std::string& key) { addUnique(output_keys_, key); }

bool State::collectProblems(std::vector<std::string>& /*problems*/) { return true; }
void State::propagateObservers(const Observers& observers) { observers_ = observers; }
void State::propagatePath(const std::string& path) { path_ = path; }

}  // namespace smachac::runtime
