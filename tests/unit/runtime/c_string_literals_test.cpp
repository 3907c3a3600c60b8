// The C-string literal forms generated code writes (StateMachine::emplace with CStringPairs,
// CStringSpec, CStringConcurrenceSpec, CallbacksLiteral, a store's set of two C strings):
// they build what the general forms build, and null strings read as "" instead of crashing.
#include <doctest/doctest.h>

#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "helpers.h"

namespace rt = smachac::runtime;
using rt::StateMachine;
using rt::UserData;
using rt::Value;

namespace {

/// Every trace line of a run of `root`.
std::vector<std::string> traceOf(rt::State& root) {
  auto sink = std::make_shared<rt::RecordingSink>();
  root.setTraceSink(sink);
  REQUIRE(rt::run(root).ok());
  return sink->lines();
}

int64_t plusTwo(UserData& ud) { return ud.get<int64_t>("n") + 2; }

/// The values `callbacks` compute, in order, from a store holding n = 5.
std::vector<Value> resultsOf(const rt::Callbacks& callbacks) {
  rt::UserDataStore store;
  store.set("n", 5);
  StateMachine holder(rt::CStringSpec{.outcomes = {"succeeded"}});
  auto& state =
      holder.emplace<rt::CallbacksState>("S", {}, {}, rt::CStringSpec{.input_keys = {"n"}});
  UserData ud(store, state);
  std::vector<Value> results;
  for (const rt::KeyedCallback& entry : callbacks) results.push_back(entry.callback(ud));
  return results;
}

}  // namespace

TEST_CASE("a CStringSpec converts to the StateSpec and StateMachineSpec with the same keys") {
  rt::CStringSpec literal{
      .outcomes = {"b", "a"}, .input_keys = {"x"}, .output_keys = {"z", nullptr}};
  rt::StateSpec spec = literal;
  CHECK(spec.outcomes == rt::Keys{"b", "a"});
  CHECK(spec.input_keys == rt::Keys{"x"});
  CHECK(spec.output_keys == rt::Keys{"z", ""});
  rt::StateMachineSpec machine = literal;
  CHECK(machine.outcomes == rt::Keys{"b", "a"});
  CHECK(machine.output_keys == rt::Keys{"z", ""});
  CHECK(machine.userdata.empty());
}

TEST_CASE("emplace builds the machine add builds, and returns the state typed") {
  auto build = [](bool emplace) {
    auto sm = std::make_unique<StateMachine>(rt::CStringSpec{.outcomes = {"done"}});
    sm->userdata().set("n", 1);
    auto spec = rt::CStringSpec{.input_keys = {"k"}, .output_keys = {"k"}};
    auto add_one = [](UserData& ud) { return ud.get<int64_t>("k") + 1; };
    if (emplace) {
      rt::CallbacksState& first =
          sm->emplace<rt::CallbacksState>("FIRST", {{"succeeded", "SECOND"}}, {{"k", "n"}}, spec,
                                          rt::CallbacksLiteral{{"k", add_one}});
      CHECK(first.outputKeys() == rt::Keys{"k"});
      sm->emplace<rt::CallbacksState>("SECOND", {{"succeeded", "done"}, {"succeeded", "FIRST"}},
                                      {{"k", "n"}}, spec, rt::CallbacksLiteral{{"k", add_one}});
    } else {
      sm->add("FIRST", std::make_unique<rt::CallbacksState>(spec, rt::Callbacks{{"k", add_one}}),
              {{"succeeded", "SECOND"}}, {{"k", "n"}});
      sm->add("SECOND", std::make_unique<rt::CallbacksState>(spec, rt::Callbacks{{"k", add_one}}),
              {{"succeeded", "done"}}, {{"k", "n"}});
    }
    return sm;
  };
  auto emplaced = build(true);
  auto added = build(false);
  CHECK(traceOf(*emplaced) == traceOf(*added));
  CHECK(emplaced->userdata().get<int64_t>("n") == 3);
  CHECK(emplaced->labels() == std::vector<std::string>{"FIRST", "SECOND"});
}

TEST_CASE("emplace reads a null label or pair string as an empty one") {
  StateMachine sm(rt::CStringSpec{.outcomes = {"done"}});
  sm.emplace<rt::PrintUserdataState>(nullptr, {{"succeeded", nullptr}}, {{nullptr, "x"}},
                                     rt::CStringSpec{});
  CHECK(sm.labels() == std::vector<std::string>{""});
  rt::Concurrence par(rt::CStringConcurrenceSpec{.outcomes = {"ok"}, .default_outcome = nullptr});
  par.emplace<rt::PrintUserdataState>(nullptr, {}, rt::CStringSpec{});
  CHECK(par.labels() == std::vector<std::string>{""});
  CHECK_THROWS_AS(par.checkConsistency(), rt::ConsistencyError);  // no default outcome
}

TEST_CASE("a CStringConcurrenceSpec means the ConcurrenceSpec with the same fields") {
  rt::ConcurrenceSpec spec = rt::CStringConcurrenceSpec{
      .outcomes = {"ok", "bad"},
      .default_outcome = "bad",
      .outcome_map = {{"ok", {{"A", "succeeded"}, {"B", "succeeded"}, {"A", "aborted"}}},
                      {"ok", {{"B", "aborted"}}}},
      .input_keys = {"x"},
      .output_keys = {"y"},
      .early_exit = false};
  CHECK(spec.outcomes == rt::Keys{"ok", "bad"});
  CHECK(spec.default_outcome == "bad");
  // The first of equal keys wins, as in OutcomeMap's initializer list.
  CHECK(spec.outcome_map == rt::OutcomeMap{{"ok", {{"A", "succeeded"}, {"B", "succeeded"}}}});
  CHECK(spec.input_keys == rt::Keys{"x"});
  CHECK(spec.output_keys == rt::Keys{"y"});
  CHECK_FALSE(spec.early_exit);
  CHECK(rt::ConcurrenceSpec(rt::CStringConcurrenceSpec{}).early_exit);

  rt::Concurrence par(rt::CStringConcurrenceSpec{.outcomes = {"ok", "bad"},
                                                 .default_outcome = "bad",
                                                 .outcome_map = {{"ok", {{"A", "done"}}}}});
  std::ostringstream log;
  par.emplace<rt::LogState>("A", {{"text", "x"}}, "hi", rt::CStringSpec{}, &log);
  auto& b = par.emplace<rt::SleepState>("B", {}, 0.0, rt::CStringSpec{.outcomes = {"done"}});
  CHECK(b.outcomes() == rt::Keys{"done"});
  CHECK(rt::run(par).outcome == "ok");
  CHECK(log.str() == "hi\n");
}

TEST_CASE("a CallbacksLiteral converts to the Callbacks of the same callables, in order") {
  int64_t offset = 10;
  int64_t (*pointer)(UserData&) = plusTwo;
  std::function<Value(UserData&)> object = [](UserData& ud) {
    return Value(ud.get<int64_t>("n") * 3);
  };
  rt::Callbacks callbacks = rt::CallbacksLiteral{
      {"lambda", [](UserData& ud) { return ud.get<int64_t>("n") + 1; }},
      {"value", [](UserData& ud) -> Value { return ud.get<int64_t>("n") - 1; }},
      {"capturing", [offset](UserData& ud) { return ud.get<int64_t>("n") + offset; }},
      {"function", plusTwo},
      {"pointer", pointer},
      {"object", object},
      {nullptr, [](UserData&) { return std::string("text"); }}};
  std::vector<std::string> keys;
  for (const rt::KeyedCallback& entry : callbacks) keys.push_back(entry.key);
  CHECK(keys == std::vector<std::string>{"lambda", "value", "capturing", "function", "pointer",
                                         "object", ""});
  CHECK(resultsOf(callbacks) == std::vector<Value>{6, 4, 15, 7, 7, 15, "text"});
  CHECK(rt::Callbacks(rt::CallbacksLiteral{}).empty());
}

TEST_CASE("a store sets two C strings as a string, and reads a null key as an empty one") {
  rt::UserDataStore store;
  const char* key = "key";
  store.set(key, "value");
  store.set(static_cast<const char*>(nullptr), "null key");
  CHECK(store.at("key") == Value(std::string("value")));
  CHECK(store.at("") == Value(std::string("null key")));
}
