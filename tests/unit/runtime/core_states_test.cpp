// The core states of SMACHA's templates.
#include <doctest/doctest.h>

#include <limits>
#include <sstream>

#include "helpers.h"

namespace rt = smachac::runtime;
using rt::StateMachine;
using rt::StateSpec;
using rt::UserData;
using rt::Value;

TEST_CASE("CallbacksState runs its callbacks in the order given and declares their keys") {
  std::vector<std::string> order;
  auto state = std::make_unique<rt::CallbacksState>(StateSpec{.input_keys = {"x", "a"}},
                                                    rt::Callbacks{{"b",
                                                                   [&](UserData& ud) -> Value {
                                                                     order.push_back("b");
                                                                     return ud.get<double>("a") + 1;
                                                                   }},
                                                                  {"a", [&](UserData& ud) -> Value {
                                                                     order.push_back("a");
                                                                     return ud.get<double>("x") * 2;
                                                                   }}});
  CHECK(state->outcomes() == rt::Keys{"succeeded"});
  CHECK(state->outputKeys() == rt::Keys{"b", "a"});
  StateMachine sm({.outcomes = {"succeeded"}, .userdata = {{"x", 3.0}, {"a", 0.5}}});
  sm.add("CB", std::move(state));
  REQUIRE(rt::run(sm).ok());
  CHECK(order == std::vector<std::string>{"b", "a"});
  CHECK(sm.userdata().get<double>("b") == 1.5);  // read `a` before the second callback set it
  CHECK(sm.userdata().get<double>("a") == 6.0);
}

TEST_CASE("PrintUserdataState prints its input keys as SMACH would") {
  std::ostringstream out;
  StateMachine sm({.outcomes = {"succeeded"},
                   .userdata = {{"animals", rt::List{"cats", "dogs"}}, {"pos", 0.15}}});
  sm.add("PRINT", std::make_unique<rt::PrintUserdataState>(
                      StateSpec{.input_keys = {"pos", "animals"}}, &out));
  REQUIRE(rt::run(sm).ok());
  CHECK(out.str() == "userdata.pos: 0.15\nuserdata.animals: ['cats', 'dogs']\n");
}

TEST_CASE("RandomOutcomeState is deterministic for a seed and records its choice") {
  auto draw = [](uint64_t seed) {
    StateMachine sm({.outcomes = {"a", "b", "c"}});
    sm.add("PICK", std::make_unique<rt::RandomOutcomeState>(StateSpec{.outcomes = {"a", "b", "c"}},
                                                            rt::Callbacks{}, seed));
    std::string choices;
    for (int i = 0; i < 12; ++i) choices += rt::run(sm).outcome;
    CHECK(sm.userdata().get<std::string>("outcome") == std::string(1, choices.back()));
    return choices;
  };
  std::string first = draw(7);
  CHECK(first == draw(7));
  CHECK(first != draw(8));
  CHECK(first.find('a') != std::string::npos);
  CHECK(first.find('b') != std::string::npos);
  CHECK(first.find('c') != std::string::npos);

  rt::RandomOutcomeState defaults;
  CHECK(defaults.outcomes() == rt::Keys{"succeeded"});
  CHECK(defaults.outputKeys() == rt::Keys{"outcome"});
}

TEST_CASE("the global seed makes unseeded random states repeatable") {
  auto draw = [] {
    StateMachine sm({.outcomes = {"a", "b"}});
    sm.add("PICK", std::make_unique<rt::RandomOutcomeState>(StateSpec{.outcomes = {"a", "b"}}));
    std::string choices;
    for (int i = 0; i < 16; ++i) choices += rt::run(sm).outcome;
    return choices;
  };
  rt::setRandomSeed(99);
  std::string first = draw();
  CHECK(first == draw());
  rt::setRandomSeed(std::nullopt);
  CHECK_FALSE(rt::randomSeed().has_value());
}

TEST_CASE("ConditionalOutcomeState returns the first outcome whose condition holds") {
  auto machine = [](double x) {
    auto sm = std::make_unique<StateMachine>(
        rt::StateMachineSpec{.outcomes = {"big", "small", "default"}, .userdata = {{"x", x}}});
    sm->add("CHOOSE",
            std::make_unique<rt::ConditionalOutcomeState>(
                StateSpec{.outcomes = {"big", "small"}, .input_keys = {"x"}},
                rt::Callbacks{
                    {"big", [](UserData& ud) -> Value { return ud.get<double>("x") > 10; }},
                    {"small", [](UserData& ud) -> Value { return ud.get<double>("x") > 0; }}}));
    return sm;
  };
  auto big = machine(20);
  CHECK(rt::run(*big).outcome == "big");
  CHECK(big->userdata().get<std::string>("outcome") == "big");
  auto small = machine(5);
  CHECK(rt::run(*small).outcome == "small");
  auto none = machine(-1);
  CHECK(rt::run(*none).outcome == "default");
  CHECK(none->userdata().get<std::string>("outcome") == "default");

  rt::ConditionalOutcomeState state(StateSpec{.outcomes = {"default", "go"}});
  CHECK(state.outcomes() == rt::Keys{"go", "default"});
  CHECK(state.inputKeys() == rt::Keys{"go"});
  CHECK(state.outputKeys() == rt::Keys{"go", "outcome"});
}

TEST_CASE("ConditionalOutcomeState skips a condition that is not set, as SMACH does") {
  StateMachine sm({.outcomes = {"first", "second", "default"},
                   .userdata = {{"second", true}, {"outcome", "stale"}}});
  sm.add("CHOOSE",
         std::make_unique<rt::ConditionalOutcomeState>(StateSpec{.outcomes = {"first", "second"}}));
  const rt::RunResult result = rt::run(sm);
  CHECK(result.error.empty());
  CHECK(result.outcome == "second");
  CHECK(sm.userdata().get<std::string>("outcome") == "second");
  CHECK_FALSE(sm.userdata().contains("first"));
}

TEST_CASE("SleepState sleeps, or returns `preempted` at once when asked and it declares it") {
  rt::SleepState nap(0.01);
  auto start = std::chrono::steady_clock::now();
  CHECK(rt::run(nap).outcome == "succeeded");
  CHECK(rt::testing::since(start) >= 0.01);
  rt::SleepState long_nap(60, {.outcomes = {"succeeded", "preempted"}});
  long_nap.requestPreempt();
  CHECK(rt::run(long_nap).outcome == "preempted");
  CHECK_FALSE(long_nap.preemptRequested());
}

TEST_CASE("SleepState without `preempted` sleeps its time and succeeds, as in SMACH") {
  rt::SleepState nap(0.05);
  nap.requestPreempt();
  auto start = std::chrono::steady_clock::now();
  CHECK(rt::run(nap).outcome == "succeeded");
  CHECK(rt::testing::since(start) >= 0.05);
}

TEST_CASE("SleepState fails on a negative or NaN time, naming the state") {
  StateMachine sm({.outcomes = {"done"}});
  sm.add("NAP", std::make_unique<rt::SleepState>(std::numeric_limits<double>::quiet_NaN()),
         {{"succeeded", "done"}});
  const rt::RunResult result = rt::run(sm);
  CHECK(result.outcome == "aborted");
  CHECK(
      result.error.find("SleepState `NAP`: the time to sleep must be 0 seconds or more, not nan") !=
      std::string::npos);
  rt::SleepState backwards(-1.0);
  CHECK(rt::run(backwards).error.find("not -1.000000") != std::string::npos);
  rt::SleepState forever(std::numeric_limits<double>::infinity(),  // until preempted
                         {.outcomes = {"succeeded", "preempted"}});
  forever.requestPreempt();
  CHECK(rt::run(forever).outcome == "preempted");
}
