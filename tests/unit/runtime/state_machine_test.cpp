// StateMachine: sequencing, transitions, container outcomes, nesting, consistency checks and
// failures in states.
#include <doctest/doctest.h>

#include <stdexcept>

#include "helpers.h"

namespace rt = smachac::runtime;
using rt::LambdaState;
using rt::StateMachine;
using rt::StateSpec;
using rt::UserData;
using rt::testing::returns;

namespace {

/// A state that appends its name to userdata `log` and returns `outcome`.
std::unique_ptr<LambdaState> logs(std::string name, std::string outcome, rt::Keys outcomes = {}) {
  if (outcomes.empty()) outcomes.push_back(outcome);
  return std::make_unique<LambdaState>(
      StateSpec{.outcomes = std::move(outcomes), .input_keys = {"log"}, .output_keys = {"log"}},
      [name, outcome](UserData& ud) {
        ud.set("log", ud.get<std::string>("log") + name);
        return outcome;
      });
}

}  // namespace

TEST_CASE("the first state added is initial and transitions sequence the states") {
  StateMachine sm({.outcomes = {"finished"}, .userdata = {{"log", ""}}});
  sm.add("A", logs("a", "next"), {{"next", "C"}});
  sm.add("B", logs("b", "next"), {{"next", "finished"}});
  sm.add("C", logs("c", "next"), {{"next", "B"}});
  auto result = rt::run(sm);
  CHECK(result.outcome == "finished");
  CHECK(sm.userdata().get<std::string>("log") == "acb");
}

TEST_CASE("a loop runs until a condition leaves it") {
  StateMachine sm({.outcomes = {"done"}, .userdata = {{"n", 0}}});
  sm.add("COUNT",
         std::make_unique<LambdaState>(
             StateSpec{.outcomes = {"again", "enough"}, .input_keys = {"n"}, .output_keys = {"n"}},
             [](UserData& ud) {
               int64_t n = ud.get<int64_t>("n") + 1;
               ud.set("n", n);
               return n < 1000 ? "again" : "enough";
             }),
         {{"again", "COUNT"}, {"enough", "done"}});
  CHECK(rt::run(sm).outcome == "done");
  CHECK(sm.userdata().get<int64_t>("n") == 1000);
}

TEST_CASE("an outcome without a transition falls through to the container outcome") {
  StateMachine sm({.outcomes = {"succeeded", "aborted"}});
  sm.add("A", returns("aborted", {"succeeded", "aborted"}), {{"succeeded", "A"}});
  CHECK(rt::run(sm).outcome == "aborted");
}

TEST_CASE("a label wins over a container outcome of the same name") {
  StateMachine sm({.outcomes = {"B", "end"}, .userdata = {{"log", ""}}});
  sm.add("A", logs("a", "go"), {{"go", "B"}});
  sm.add("B", logs("b", "stop"), {{"stop", "end"}});
  CHECK(rt::run(sm).outcome == "end");
  CHECK(sm.userdata().get<std::string>("log") == "ab");
}

TEST_CASE("nested machines return their outcome to the parent's transitions") {
  StateMachine root({.outcomes = {"ok", "failed"}, .userdata = {{"log", ""}}});
  auto& sub =
      root.add("SUB",
               std::make_unique<StateMachine>(rt::StateMachineSpec{
                   .outcomes = {"inner_done"}, .input_keys = {"log"}, .output_keys = {"log"}}),
               {{"inner_done", "AFTER"}});
  root.add("AFTER", logs("z", "ok"));
  sub.add("X", logs("x", "next"), {{"next", "Y"}});
  sub.add("Y", logs("y", "inner_done"));
  CHECK(root.child("SUB").path() == "SUB");
  CHECK(sub.child("Y").path() == "SUB/Y");
  auto result = rt::run(root);
  CHECK(result.outcome == "ok");
  CHECK(root.userdata().get<std::string>("log") == "xyz");
}

TEST_CASE("the consistency check lists every problem, naming the state") {
  StateMachine sm({.outcomes = {"succeeded"}});
  sm.add("A", returns("next", {"next", "failed"}), {{"next", "BB"}, {"bogus", "A"}});
  sm.add("B", returns("succeeded"));
  auto& sub = sm.add("SUB", std::make_unique<StateMachine>(rt::StateMachineSpec{.outcomes = {"x"}}),
                     {{"x", "succeeded"}});
  (void)sub;
  CHECK_THROWS_WITH_AS(
      sm.checkConsistency(),
      "state `A`: transition from `bogus`, which is not one of its outcomes\n"
      "state `A`: outcome `next` goes to `BB`, which is neither a state nor an outcome of state "
      "machine `root`\n"
      "state `A`: outcome `failed` has no transition and is not an outcome of state machine "
      "`root`\n"
      "state machine `SUB` has no states",
      rt::ConsistencyError);
  auto result = rt::run(sm);
  CHECK(result.outcome == "aborted");
  CHECK(result.error.starts_with("state `A`: transition from `bogus`"));
}

TEST_CASE("duplicate labels and empty machines are reported") {
  StateMachine empty({.outcomes = {"done"}});
  CHECK_THROWS_WITH_AS(empty.checkConsistency(), "state machine `root` has no states",
                       rt::ConsistencyError);
  StateMachine twice({.outcomes = {"done"}});
  twice.add("A", returns("done"));
  twice.add("A", returns("done"));
  CHECK_THROWS_WITH_AS(twice.checkConsistency(), "state machine `root` has two states labelled `A`",
                       rt::ConsistencyError);
  CHECK_THROWS_WITH_AS(twice.add("NULL", std::unique_ptr<LambdaState>()),
                       "state machine `root`: state `NULL` is null", rt::Error);
  CHECK(twice.size() == 2);
}

TEST_CASE("a LambdaState without a callable is rejected when it is built") {
  CHECK_THROWS_WITH_AS(LambdaState(StateSpec{.outcomes = {"done"}}, LambdaState::Body{}),
                       "a LambdaState needs a callable, got an empty one", rt::Error);
  CHECK_THROWS_WITH_AS(LambdaState(StateSpec{.outcomes = {"done"}}, LambdaState::BodyWithState{}),
                       "a LambdaState needs a callable, got an empty one", rt::Error);
}

TEST_CASE("an undeclared outcome stops the machine with an error") {
  StateMachine sm({.outcomes = {"done"}});
  sm.add("A", std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}},
                                            [](UserData&) { return "oops"; }));
  auto result = rt::run(sm);
  CHECK(result.outcome == "aborted");
  CHECK(result.error == "state `A` returned outcome `oops`, which is not one of its outcomes");
}

TEST_CASE("exceptions in states become an aborted result naming the state") {
  StateMachine root({.outcomes = {"done"}});
  auto& sub =
      root.add("SUB", std::make_unique<StateMachine>(rt::StateMachineSpec{.outcomes = {"done"}}));
  sub.add("BOOM", std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}},
                                                [](UserData&) -> std::string {
                                                  throw std::runtime_error("gripper jammed");
                                                }));
  auto result = rt::run(root);
  CHECK(result.outcome == "aborted");
  CHECK(result.error == "state `SUB/BOOM` failed: gripper jammed");
  CHECK_THROWS_WITH_AS(root.child("MISSING"), "state machine `root` has no state `MISSING`",
                       rt::Error);
}

TEST_CASE("exceptions that are not std::exception are reported too") {
  StateMachine sm({.outcomes = {"done"}});
  sm.add("INT", std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}},
                                              [](UserData&) -> std::string { throw 42; }));
  CHECK(rt::run(sm).error == "state `INT` failed: unknown exception");
  // The machine can run again after a failure.
  CHECK(rt::run(sm).error == "state `INT` failed: unknown exception");
}

TEST_CASE("a leaf state can be the root") {
  auto leaf = returns("done");
  CHECK(rt::run(*leaf).outcome == "done");
}
