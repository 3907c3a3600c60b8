// Preemption from another thread: it reaches every running child of nested and concurrent
// machines, and the machine returns `preempted` within a bounded time. Also built with
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

/// A machine looping forever through two states, without sleeping.
std::unique_ptr<StateMachine> spinner() {
  auto sm = std::make_unique<StateMachine>(machine());
  sm->add("PING",
          std::make_unique<LambdaState>(StateSpec{.outcomes = {"next"}},
                                        [](UserData&) { return "next"; }),
          {{"next", "PONG"}});
  sm->add("PONG",
          std::make_unique<LambdaState>(StateSpec{.outcomes = {"next"}},
                                        [](UserData&) { return "next"; }),
          {{"next", "PING"}});
  return sm;
}

}  // namespace

TEST_CASE("preempting a nested machine reaches the sleeping leaf") {
  StateMachine root(machine());
  auto& sub =
      root.add("SUB", std::make_unique<StateMachine>(machine()), {{"succeeded", "succeeded"}});
  sub.add("SLEEP",
          std::make_unique<SleepState>(30.0, StateSpec{.outcomes = {"succeeded", "preempted"}}));
  auto sink = std::make_shared<rt::RecordingSink>();
  root.setTraceSink(sink);
  auto start = std::chrono::steady_clock::now();
  auto result = runAndPreempt(root, 50ms);
  CHECK(result.outcome == "preempted");
  CHECK(since(start) < 2.0);
  auto lines = sink->lines();
  CHECK(std::find(lines.begin(), lines.end(), "preempt SUB/SLEEP") != lines.end());
  CHECK(lines.back() == "exit  preempted");
}

TEST_CASE("preempting a concurrence reaches every concurrent child") {
  StateMachine root(machine());
  auto& con = root.add("CON",
                       std::make_unique<Concurrence>(rt::ConcurrenceSpec{
                           .outcomes = {"succeeded", "preempted"}, .default_outcome = "succeeded"}),
                       {{"succeeded", "succeeded"}});
  auto& left = con.add("LEFT", std::make_unique<StateMachine>(machine()));
  left.add("MOVE", std::make_unique<SleepState>(30.0), {{"succeeded", "MOVE"}});
  auto& right = con.add("RIGHT", std::make_unique<StateMachine>(machine()));
  right.add("WAIT", waitsForPreempt(), {{"done", "succeeded"}});
  con.add("SPIN", spinner());
  con.add("NAP", std::make_unique<SleepState>(30.0));
  auto start = std::chrono::steady_clock::now();
  auto result = runAndPreempt(root, 50ms);
  CHECK(result.outcome == "preempted");
  CHECK(since(start) < 2.0);
}

TEST_CASE("a fast loop is preempted between two states") {
  for (int round = 0; round < 20; ++round) {
    auto sm = spinner();
    auto result = runAndPreempt(*sm, std::chrono::milliseconds(round % 3));
    CHECK(result.outcome == "preempted");
  }
}

TEST_CASE("a preempt requested before the run preempts it at once, and only once") {
  auto sm = spinner();
  sm->requestPreempt();
  CHECK(rt::run(*sm).outcome == "preempted");
  CHECK_FALSE(sm->preemptRequested());
  // The next run is a fresh one: it is preempted again only when asked again.
  CHECK(runAndPreempt(*sm, 5ms).outcome == "preempted");
  CHECK(runAndPreempt(*sm, 5ms).outcome == "preempted");
}

TEST_CASE("a state that ignores the request delays, but does not prevent, `preempted`") {
  StateMachine sm(machine());
  std::atomic<bool> finished{false};
  sm.add("STUBBORN",
         std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}},
                                       [&](UserData&) {
                                         std::this_thread::sleep_for(100ms);
                                         finished = true;
                                         return "done";
                                       }),
         {{"done", "succeeded"}});
  auto result = runAndPreempt(sm, 10ms);
  CHECK(result.outcome == "preempted");
  CHECK(finished);
  CHECK_FALSE(sm.child("STUBBORN").preemptRequested());
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

TEST_CASE("many concurrent runs and preempts stay consistent") {
  for (int round = 0; round < 10; ++round) {
    Concurrence con({.outcomes = {"succeeded", "preempted"}, .default_outcome = "succeeded"});
    for (int i = 0; i < 4; ++i) con.add("S" + std::to_string(i), spinner());
    con.add("SLEEP", std::make_unique<SleepState>(10.0));
    auto result = runAndPreempt(con, std::chrono::milliseconds(1 + round % 4));
    CHECK(result.outcome == "preempted");
  }
}
