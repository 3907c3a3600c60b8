// Concurrence: outcome_map, default_outcome, early exit, child termination and outcome
// callbacks, failures in children. Also built with ThreadSanitizer (label tsan).
#include <doctest/doctest.h>

#include <atomic>
#include <stdexcept>

#include "helpers.h"

namespace rt = smachac::runtime;
using namespace std::chrono_literals;
using rt::Concurrence;
using rt::ConcurrenceSpec;
using rt::LambdaState;
using rt::State;
using rt::StateSpec;
using rt::UserData;
using rt::testing::returns;
using rt::testing::since;
using rt::testing::waitsForPreempt;

namespace {

ConcurrenceSpec spec(rt::OutcomeMap map) {
  return {.outcomes = {"succeeded", "aborted", "mixed"},
          .default_outcome = "aborted",
          .outcome_map = std::move(map)};
}

/// A state that returns `done` after 50 ms, or at once when preempted; `finished` tells which.
std::unique_ptr<LambdaState> slowDone(std::atomic<bool>& finished) {
  return std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}},
                                       [&finished](State& self, UserData&) -> std::string {
                                         finished = !self.waitForPreempt(50ms);
                                         return "done";
                                       });
}

}  // namespace

TEST_CASE("all children run and the outcome map picks the container outcome") {
  Concurrence con(spec({{"succeeded", {{"A", "done"}, {"B", "done"}}}}));
  con.add("A", returns("done"));
  con.add("B", returns("done"));
  CHECK(rt::run(con).outcome == "succeeded");
}

TEST_CASE("the default outcome applies when no entry is satisfied") {
  Concurrence con(spec({{"succeeded", {{"A", "done"}, {"B", "done"}}}}));
  con.add("A", returns("done"));
  con.add("B", returns("failed"));
  CHECK(rt::run(con).outcome == "aborted");
}

// The outcome_map rule (stdlib/runtime/README.md, "Choosing among outcome_map entries"). Map
// order is the order of the outcome names: `mixed` comes before `succeeded`.
TEST_CASE("of two satisfied entries the one with more conditions wins, in either order") {
  Concurrence larger_first(
      spec({{"mixed", {{"A", "done"}, {"B", "done"}}}, {"succeeded", {{"A", "done"}}}}));
  larger_first.add("A", returns("done"));
  larger_first.add("B", returns("done"));
  CHECK(rt::run(larger_first).outcome == "mixed");

  Concurrence larger_last(
      spec({{"mixed", {{"A", "done"}}}, {"succeeded", {{"A", "done"}, {"B", "done"}}}}));
  larger_last.add("A", returns("done"));
  larger_last.add("B", returns("done"));
  CHECK(rt::run(larger_last).outcome == "succeeded");
}

TEST_CASE("of satisfied entries with equally many conditions the first in map order wins") {
  Concurrence tie(spec({{"mixed", {{"A", "done"}}}, {"succeeded", {{"B", "done"}}}}));
  tie.add("A", returns("done"));
  tie.add("B", returns("done"));
  tie.add("C", returns("done"));
  CHECK(rt::run(tie).outcome == "mixed");
}

TEST_CASE("an entry without conditions is never chosen") {
  Concurrence alone(spec({{"mixed", {}}}));
  alone.add("A", returns("done"));
  CHECK(rt::run(alone).outcome == "aborted");

  Concurrence before_unsatisfied(spec({{"mixed", {}}, {"succeeded", {{"A", "done"}}}}));
  before_unsatisfied.add("A", returns("failed"));
  CHECK(rt::run(before_unsatisfied).outcome == "aborted");

  Concurrence before_satisfied(spec({{"mixed", {}}, {"succeeded", {{"A", "done"}}}}));
  before_satisfied.add("A", returns("done"));
  CHECK(rt::run(before_satisfied).outcome == "succeeded");
}

TEST_CASE("a decided entry preempts the children still running") {
  Concurrence con(spec(
      {{"aborted", {{"FAIL", "failed"}}}, {"succeeded", {{"FAIL", "done"}, {"WAIT", "done"}}}}));
  con.add("FAIL", returns("failed", {"failed", "done"}));
  con.add("WAIT", waitsForPreempt());
  auto start = std::chrono::steady_clock::now();
  CHECK(rt::run(con).outcome == "aborted");
  CHECK(since(start) < 5.0);
}

TEST_CASE("an entry that could still be beaten does not decide early") {
  // FAST returns first, satisfying `mixed`; `succeeded` names more children and SLOW may still
  // satisfy it, so the container waits for SLOW.
  std::atomic<bool> slow_finished{false};
  Concurrence larger_later(
      spec({{"mixed", {{"FAST", "done"}}}, {"succeeded", {{"FAST", "done"}, {"SLOW", "done"}}}}));
  larger_later.add("FAST", returns("done"));
  larger_later.add("SLOW", slowDone(slow_finished));
  CHECK(rt::run(larger_later).outcome == "succeeded");
  CHECK(slow_finished);

  // FAST satisfies `succeeded`; `mixed` has as many conditions and comes first, so it still
  // outranks `succeeded` while SLOW runs.
  slow_finished = false;
  Concurrence tie_earlier(spec({{"mixed", {{"SLOW", "done"}}}, {"succeeded", {{"FAST", "done"}}}}));
  tie_earlier.add("FAST", returns("done"));
  tie_earlier.add("SLOW", slowDone(slow_finished));
  CHECK(rt::run(tie_earlier).outcome == "mixed");
  CHECK(slow_finished);
}

TEST_CASE("an entry without conditions never decides early") {
  std::atomic<bool> slow_finished{false};
  Concurrence con(spec({{"mixed", {}}, {"succeeded", {{"SLOW", "done"}}}}));
  con.add("FAST", returns("done"));
  con.add("SLOW", slowDone(slow_finished));
  CHECK(rt::run(con).outcome == "succeeded");
  CHECK(slow_finished);
}

TEST_CASE("without early exit every child runs to its end") {
  ConcurrenceSpec s = spec({{"aborted", {{"FAIL", "failed"}}}});
  s.early_exit = false;
  Concurrence con(std::move(s));
  std::atomic<bool> preempted{false};
  con.add("FAIL", returns("failed"));
  con.add("SLOW", std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}},
                                                [&](State& self, UserData&) -> std::string {
                                                  preempted = self.waitForPreempt(30ms);
                                                  return "done";
                                                }));
  CHECK(rt::run(con).outcome == "aborted");
  CHECK_FALSE(preempted);
}

TEST_CASE("the child termination callback sees outcomes so far and can preempt the others") {
  ConcurrenceSpec s = spec({{"succeeded", {{"MONITOR", "triggered"}}}});
  std::vector<rt::ChildOutcomes> seen;
  s.child_termination_cb = [&](const rt::ChildOutcomes& outcomes) {
    seen.push_back(outcomes);
    return outcomes.contains("MONITOR");
  };
  s.early_exit = false;
  Concurrence con(std::move(s));
  con.add("MONITOR", returns("triggered"));
  con.add("WORK", waitsForPreempt());
  CHECK(rt::run(con).outcome == "succeeded");
  REQUIRE(seen.size() == 2);
  CHECK(seen[0] == rt::ChildOutcomes{{"MONITOR", "triggered"}});
  CHECK(seen[1] == rt::ChildOutcomes{{"MONITOR", "triggered"}, {"WORK", "preempted"}});
}

TEST_CASE("the outcome callback comes first") {
  ConcurrenceSpec s = spec({{"succeeded", {{"A", "done"}}}});
  s.outcome_cb = [](const rt::ChildOutcomes& outcomes) -> std::string {
    return outcomes.at("B") == "odd" ? "mixed" : "";
  };
  Concurrence con(std::move(s));
  con.add("A", returns("done"));
  con.add("B", returns("odd"));
  CHECK(rt::run(con).outcome == "mixed");

  ConcurrenceSpec bad = spec({});
  bad.outcome_cb = [](const rt::ChildOutcomes&) -> std::string { return "nope"; };
  Concurrence con2(std::move(bad));
  con2.add("A", returns("done"));
  CHECK(rt::run(con2).error ==
        "concurrence `root`: outcome callback returned `nope`, which is not one of its outcomes");
}

TEST_CASE("children share the container's userdata through their remappings") {
  ConcurrenceSpec s = spec({{"succeeded", {{"LEFT", "done"}, {"RIGHT", "done"}}}});
  s.userdata = {{"speed", 2.0}};
  Concurrence con(std::move(s));
  auto arm = [] {
    return std::make_unique<LambdaState>(
        StateSpec{.outcomes = {"done"}, .input_keys = {"speed"}, .output_keys = {"pos"}},
        [](UserData& ud) {
          for (int i = 0; i < 200; ++i) ud.set("pos", ud.get<double>("speed") * i);
          return "done";
        });
  };
  con.add("LEFT", arm(), {{"pos", "left_pos"}});
  con.add("RIGHT", arm(), {{"pos", "right_pos"}});
  CHECK(rt::run(con).outcome == "succeeded");
  CHECK(con.userdata().get<double>("left_pos") == 398.0);
  CHECK(con.userdata().get<double>("right_pos") == 398.0);
}

TEST_CASE("a failing child preempts the others and fails the container") {
  Concurrence con(spec({}));
  con.add("WAIT", waitsForPreempt());
  con.add("BOOM", std::make_unique<LambdaState>(
                      StateSpec{.outcomes = {"done"}},
                      [](UserData&) -> std::string { throw std::runtime_error("sensor lost"); }));
  auto start = std::chrono::steady_clock::now();
  auto result = rt::run(con);
  CHECK(result.outcome == "aborted");
  CHECK(result.error == "state `BOOM` failed: sensor lost");
  CHECK(since(start) < 5.0);
}

TEST_CASE("the outcome policy is checked") {
  Concurrence con(
      {.outcomes = {"succeeded"},
       .default_outcome = "aborted",
       .outcome_map = {{"won", {{"A", "done"}}}, {"succeeded", {{"Z", "done"}, {"A", "odd"}}}}});
  con.add("A", returns("done"));
  CHECK_THROWS_WITH_AS(con.checkConsistency(),
                       "concurrence `root`: default outcome `aborted` is not one of its outcomes\n"
                       "concurrence `root`: outcome map entry `succeeded` expects outcome `odd` of "
                       "`A`, which is not "
                       "one of its outcomes\n"
                       "concurrence `root`: outcome map entry `succeeded` names `Z`, which is not "
                       "one of its states\n"
                       "concurrence `root`: outcome map entry `won` is not one of its outcomes",
                       rt::ConsistencyError);
  Concurrence empty({.outcomes = {"done"}});
  CHECK_THROWS_WITH_AS(
      empty.checkConsistency(),
      "concurrence `root` has no states\nconcurrence `root` has no default outcome",
      rt::ConsistencyError);
}

TEST_CASE("a concurrence inside a state machine, run many times") {
  rt::StateMachine sm({.outcomes = {"done"}, .userdata = {{"n", 0}}});
  auto& con = sm.add(
      "PAR",
      std::make_unique<Concurrence>(ConcurrenceSpec{
          .outcomes = {"ok"}, .default_outcome = "ok", .input_keys = {"n"}, .output_keys = {"n"}}),
      {{"ok", "COUNT"}});
  con.add("A", returns("done"));
  con.add("B", std::make_unique<LambdaState>(
                   StateSpec{.outcomes = {"done"}, .input_keys = {"n"}, .output_keys = {"n"}},
                   [](UserData& ud) {
                     ud.set("n", ud.get<int64_t>("n") + 1);
                     return "done";
                   }));
  sm.add("COUNT",
         std::make_unique<LambdaState>(
             StateSpec{.outcomes = {"again", "done"}, .input_keys = {"n"}},
             [](UserData& ud) { return ud.get<int64_t>("n") < 50 ? "again" : "done"; }),
         {{"again", "PAR"}});
  CHECK(rt::run(sm).outcome == "done");
  CHECK(sm.userdata().get<int64_t>("n") == 50);
}

TEST_CASE("a null child is rejected before it is used") {
  Concurrence par(spec({}));
  CHECK_THROWS_WITH_AS(par.add("NULL", std::unique_ptr<LambdaState>()),
                       "concurrence `root`: state `NULL` is null", rt::Error);
  CHECK(par.size() == 0);
}
