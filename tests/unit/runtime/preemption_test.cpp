// Preemption from another thread, by SMACH 2.5's rules: a request reaches every running child
// of nested and concurrent machines; a serviced request is done with and the machine follows
// the child's outcome; an ignored one is passed on to the next state. Also built with
// ThreadSanitizer (label tsan).
#include <doctest/doctest.h>

#include <atomic>
#include <thread>

#include "helpers.h"

namespace rt = smachac::runtime;
using namespace std::chrono_literals;
using rt::Concurrence;
using rt::LambdaState;
using rt::SleepState;
using rt::State;
using rt::StateMachine;
using rt::StateSpec;
using rt::UserData;
using rt::testing::since;
using rt::testing::waitsForPreempt;

namespace {

rt::StateMachineSpec machine() { return {.outcomes = {"succeeded", "preempted"}}; }

/// Runs `root` on this thread and preempts it from another after `delay`.
rt::RunResult runAndPreempt(rt::State& root, std::chrono::milliseconds delay) {
  std::jthread preempter([&root, delay] {
    std::this_thread::sleep_for(delay);
    root.requestPreempt();
  });
  return rt::run(root);
}

/// A sleep of `seconds` that services a preempt (it declares `preempted`).
std::unique_ptr<SleepState> nap(double seconds) {
  return std::make_unique<SleepState>(seconds, StateSpec{.outcomes = {"succeeded", "preempted"}});
}

/// A machine sleeping in a loop until it is preempted.
std::unique_ptr<StateMachine> napper() {
  auto sm = std::make_unique<StateMachine>(machine());
  sm->add("NAP", nap(10.0), {{"succeeded", "NAP"}});
  return sm;
}

/// A state that ignores preemption: it works for `time`, then returns `done`.
std::unique_ptr<LambdaState> stubborn(std::chrono::milliseconds time) {
  return std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}}, [time](UserData&) {
    std::this_thread::sleep_for(time);
    return "done";
  });
}

/// A state that records whether it started with a preempt request, then returns `done`.
std::unique_ptr<LambdaState> records(std::atomic<bool>& asked) {
  return std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}},
                                       [&asked](State& self, UserData&) -> std::string {
                                         asked = self.preemptRequested();
                                         return "done";
                                       });
}

}  // namespace

TEST_CASE("preempting a nested machine reaches the sleeping leaf") {
  StateMachine root(machine());
  auto& sub =
      root.add("SUB", std::make_unique<StateMachine>(machine()), {{"succeeded", "succeeded"}});
  sub.add("SLEEP", nap(30.0));
  auto sink = std::make_shared<rt::RecordingSink>();
  root.setTraceSink(sink);
  auto start = std::chrono::steady_clock::now();
  auto result = runAndPreempt(root, 50ms);
  CHECK(result.outcome == "preempted");
  CHECK(since(start) < 2.0);
  auto lines = sink->lines();
  CHECK(std::find(lines.begin(), lines.end(), "preempt SUB/SLEEP") != lines.end());
  CHECK(lines.back() == "exit  preempted");
  CHECK_FALSE(root.preemptRequested());
}

TEST_CASE("a serviced request is done with: the machine follows the state's outcome") {
  StateMachine sm({.outcomes = {"succeeded", "recovered"}});
  std::atomic<bool> asked{true};
  sm.add("WAIT", waitsForPreempt(), {{"preempted", "RECOVER"}, {"done", "succeeded"}});
  sm.add("RECOVER", records(asked), {{"done", "recovered"}});
  CHECK(runAndPreempt(sm, 30ms).outcome == "recovered");
  CHECK_FALSE(asked);
  CHECK_FALSE(sm.preemptRequested());
}

TEST_CASE("a request the running state ignores is passed on to the next state") {
  StateMachine sm(machine());
  auto& first = sm.add("STUBBORN", stubborn(100ms), {{"done", "WAIT"}});
  sm.add("WAIT", waitsForPreempt(), {{"done", "succeeded"}});
  auto start = std::chrono::steady_clock::now();
  CHECK(runAndPreempt(sm, 10ms).outcome == "preempted");
  CHECK(since(start) < 2.0);
  CHECK_FALSE(first.preemptRequested());
}

TEST_CASE("a request no state services leaves the outcome as the transitions give it") {
  StateMachine sm(machine());
  std::atomic<bool> asked{false};
  auto& first = sm.add("STUBBORN", stubborn(60ms), {{"done", "RECORD"}});
  auto& second = sm.add("RECORD", records(asked), {{"done", "succeeded"}});
  CHECK(runAndPreempt(sm, 10ms).outcome == "succeeded");
  CHECK(asked);
  CHECK_FALSE(first.preemptRequested());
  CHECK_FALSE(second.preemptRequested());
  CHECK_FALSE(sm.preemptRequested());  // taken back when the run ends
}

TEST_CASE("a preempt requested before the run preempts its first state, and only that run") {
  auto sm = napper();
  sm->requestPreempt();
  CHECK(rt::run(*sm).outcome == "preempted");
  CHECK_FALSE(sm->preemptRequested());
  // The next run is a fresh one: it is preempted again only when asked again.
  CHECK(runAndPreempt(*sm, 5ms).outcome == "preempted");
  CHECK(runAndPreempt(*sm, 5ms).outcome == "preempted");
}

TEST_CASE("returning an undeclared `preempted` is an error, as in SMACH") {
  StateMachine sm(machine());
  sm.add("EAGER",
         std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}},
                                       [](UserData&) { return "preempted"; }),
         {{"done", "succeeded"}});
  const rt::RunResult result = rt::run(sm);
  CHECK(result.outcome == "aborted");
  CHECK(result.error ==
        "state `EAGER` returned outcome `preempted`, which is not one of its outcomes");
}

TEST_CASE("a child preempted on its own follows its `preempted` transition") {
  StateMachine sm({.outcomes = {"succeeded", "recovered"}});
  auto& waiting =
      sm.add("WAIT", waitsForPreempt(), {{"preempted", "RECOVER"}, {"done", "succeeded"}});
  sm.add("RECOVER", std::make_unique<LambdaState>(StateSpec{.outcomes = {"recovered"}},
                                                  [](UserData&) { return "recovered"; }));
  std::jthread poke([&waiting] {
    std::this_thread::sleep_for(30ms);
    waiting.requestPreempt();
  });
  CHECK(rt::run(sm).outcome == "recovered");
}

TEST_CASE("preempting a concurrence reaches every concurrent child") {
  StateMachine root(machine());
  auto& con = root.add("CON",
                       std::make_unique<Concurrence>(rt::ConcurrenceSpec{
                           .outcomes = {"succeeded", "preempted"}, .default_outcome = "succeeded"}),
                       {{"succeeded", "succeeded"}});
  con.add("LEFT", napper());
  auto& right = con.add("RIGHT", std::make_unique<StateMachine>(machine()));
  right.add("WAIT", waitsForPreempt(), {{"done", "succeeded"}});
  con.add("NAP", nap(30.0));
  auto start = std::chrono::steady_clock::now();
  auto result = runAndPreempt(root, 50ms);
  CHECK(result.outcome == "preempted");
  CHECK(since(start) < 2.0);
}

TEST_CASE("a concurrence with a child that ignored the request keeps its usual outcome") {
  Concurrence con({.outcomes = {"succeeded", "preempted"}, .default_outcome = "succeeded"});
  con.add("WAIT", waitsForPreempt());
  auto& stubborn_child = con.add("STUBBORN", stubborn(100ms));
  CHECK(runAndPreempt(con, 20ms).outcome == "succeeded");
  CHECK_FALSE(stubborn_child.preemptRequested());
}

TEST_CASE("a concurrence asked before it starts starts every child preempted") {
  Concurrence con({.outcomes = {"succeeded", "preempted"}, .default_outcome = "succeeded"});
  con.add("LEFT", napper());
  con.add("NAP", nap(30.0));
  con.requestPreempt();
  auto start = std::chrono::steady_clock::now();
  CHECK(rt::run(con).outcome == "preempted");
  CHECK(since(start) < 2.0);
}

TEST_CASE("many concurrent runs and preempts stay consistent") {
  for (int round = 0; round < 10; ++round) {
    Concurrence con({.outcomes = {"succeeded", "preempted"}, .default_outcome = "succeeded"});
    for (int i = 0; i < 4; ++i) con.add("S" + std::to_string(i), napper());
    con.add("SLEEP", nap(10.0));
    auto result = runAndPreempt(con, std::chrono::milliseconds(1 + round % 4));
    CHECK(result.outcome == "preempted");
  }
}
