// The literal forms generated code writes (SpecLiteral, PairsLiteral, a store's set of a string
// literal) and Callback: they mean what the owning forms mean.
#include <doctest/doctest.h>

#include <functional>
#include <memory>
#include <string>

#include "helpers.h"

namespace rt = smachac::runtime;
using rt::StateMachine;
using rt::UserData;
using rt::Value;

namespace {

/// The transitions a machine followed, one "FROM outcome TARGET" line each.
std::vector<std::string> transitions(StateMachine& sm) {
  auto sink = std::make_shared<rt::RecordingSink>();
  sm.setTraceSink(sink);
  REQUIRE(rt::run(sm).ok());
  std::vector<std::string> out;
  for (const std::string& line : sink->lines()) {
    if (line.rfind("transition ", 0) == 0) out.push_back(line.substr(11));
  }
  return out;
}

int64_t twice(UserData& ud) { return 2 * ud.get<int64_t>("n"); }

}  // namespace

TEST_CASE("a SpecLiteral converts to the StateSpec with the same keys in the same order") {
  rt::StateSpec spec =
      rt::SpecLiteral{.outcomes = {"b", "a"}, .input_keys = {"x"}, .output_keys = {"z", "y"}};
  CHECK(spec.outcomes == rt::Keys{"b", "a"});
  CHECK(spec.input_keys == rt::Keys{"x"});
  CHECK(spec.output_keys == rt::Keys{"z", "y"});
  auto state = std::make_unique<rt::CallbacksState>(rt::SpecLiteral{.input_keys = {"x"}});
  CHECK(state->outcomes() == rt::Keys{"succeeded"});
  CHECK(state->inputKeys() == rt::Keys{"x"});
}

TEST_CASE("toMap keeps the first of equal keys, as a std::map's initializer list does") {
  CHECK(rt::toMap({{"a", "1"}, {"b", "2"}, {"a", "3"}}) ==
        rt::Remapping{{"a", "1"}, {"b", "2"}, {"a", "3"}});
  CHECK(rt::toMap({}).empty());
}

TEST_CASE("literal and owning transitions and remappings lead to the same states") {
  auto build = [](bool literal) {
    auto sm = std::make_unique<StateMachine>(
        rt::StateMachineSpec{.outcomes = {"done"}, .userdata = {{"n", 1}}});
    auto inc = [] {
      return std::make_unique<rt::CallbacksState>(
          rt::SpecLiteral{.input_keys = {"k"}, .output_keys = {"k"}},
          rt::Callbacks{{"k", [](UserData& ud) { return ud.get<int64_t>("k") + 1; }}});
    };
    std::string next = "SECOND";  // not a literal: a string that outlives the statement
    if (literal) {
      sm->add("FIRST", inc(), {{"succeeded", next}}, {{"k", "n"}});
      sm->add("SECOND", inc(), {{"succeeded", "done"}}, {{"k", "n"}});
    } else {
      sm->add("FIRST", inc(), rt::Transitions{{"succeeded", next}}, rt::Remapping{{"k", "n"}});
      sm->add("SECOND", inc(), rt::Transitions{{"succeeded", "done"}}, {{"k", "n"}});
    }
    return sm;
  };
  auto literal = build(true);
  auto owning = build(false);
  CHECK(transitions(*literal) == transitions(*owning));
  CHECK(literal->userdata().get<int64_t>("n") == 3);
  CHECK(owning->userdata().get<int64_t>("n") == 3);
}

TEST_CASE("a Concurrence takes its children's remapping as a literal or a map") {
  rt::Concurrence par(rt::ConcurrenceSpec{.outcomes = {"ok"}, .default_outcome = "ok"});
  auto copy = [] {
    return std::make_unique<rt::CallbacksState>(
        rt::SpecLiteral{.input_keys = {"in"}},
        rt::Callbacks{{"out", [](UserData& ud) { return ud.get<std::string>("in"); }}});
  };
  par.add("A", copy(), {{"in", "x"}, {"out", "a"}});
  par.add("B", copy(), rt::Remapping{{"in", "x"}, {"out", "b"}});
  par.userdata().set("x", "text");
  REQUIRE(rt::run(par).ok());
  CHECK(par.userdata().get<std::string>("a") == "text");
  CHECK(par.userdata().get<std::string>("b") == "text");
}

TEST_CASE("a store sets a string literal as a string, and 0 and nullptr as before") {
  rt::UserDataStore store;
  store.set("text", "step 0");
  store.set("zero", 0);
  store.set("int_zero", int64_t{0});
  store.set("null", nullptr);
  const char* pointer = "pointed";
  store.set("pointer", pointer);
  CHECK(store.at("text") == Value(std::string("step 0")));
  CHECK(store.at("zero").type() == rt::ValueType::Int);
  CHECK(store.at("int_zero").type() == rt::ValueType::Int);
  CHECK(store.at("null").isNull());
  CHECK(store.at("pointer") == Value(std::string("pointed")));
}

TEST_CASE("a Callback calls functions, lambdas and function objects alike") {
  rt::UserDataStore store;
  store.set("n", 5);
  rt::StateMachine holder(rt::StateMachineSpec{.outcomes = {"succeeded"}});
  auto& state = holder.add("S", std::make_unique<rt::CallbacksState>(
                                    rt::SpecLiteral{.input_keys = {"n"}, .output_keys = {"n"}}));
  UserData ud(store, state);
  int64_t offset = 10;
  rt::Callback none;
  rt::Callback function = twice;
  rt::Callback lambda = [](UserData& u) { return u.get<int64_t>("n") + 1; };
  rt::Callback capturing = [offset](UserData& u) { return u.get<int64_t>("n") + offset; };
  rt::Callback wrapped = std::function<Value(UserData&)>(lambda);
  rt::Callback copied = lambda;
  CHECK_FALSE(none);
  CHECK_THROWS_AS(none(ud), std::bad_function_call);
  CHECK(function(ud) == Value(10));
  CHECK(lambda(ud) == Value(6));
  CHECK(capturing(ud) == Value(15));
  CHECK(wrapped(ud) == Value(6));
  CHECK(copied(ud) == Value(6));
  CHECK(static_cast<bool>(capturing));
}
