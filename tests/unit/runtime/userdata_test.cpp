// Userdata: scopes, remapping, declared keys and their error messages, typed reads.
#include <doctest/doctest.h>

#include "helpers.h"

namespace rt = smachac::runtime;
using rt::LambdaState;
using rt::StateMachine;
using rt::StateSpec;
using rt::UserData;
using rt::Value;

namespace {

/// A one-state machine around `body`, run through rt::run; returns the result.
rt::RunResult runOne(StateSpec spec, LambdaState::Body body, rt::Remapping remapping = {},
                     rt::Map userdata = {}, StateMachine** keep = nullptr) {
  static std::unique_ptr<StateMachine> last;
  last = std::make_unique<StateMachine>(
      rt::StateMachineSpec{.outcomes = {"done"}, .userdata = std::move(userdata)});
  last->add("FOO", std::make_unique<LambdaState>(std::move(spec), std::move(body)), {},
            std::move(remapping));
  if (keep != nullptr) *keep = last.get();
  return rt::run(*last);
}

}  // namespace

TEST_CASE("the store reports missing and mistyped keys") {
  rt::UserDataStore store(rt::Map{{"x", 1.5}});
  CHECK(store.get<double>("x") == 1.5);
  CHECK(store.keys() == std::vector<std::string>{"x"});
  CHECK_THROWS_WITH_AS(store.get<double>("y"), "userdata key `y` is not set", rt::UserDataError);
  CHECK_THROWS_WITH_AS(store.get<std::string>("x"), "userdata key `x` holds a double, not a string",
                       rt::UserDataError);
}

TEST_CASE("a state reads and writes its parent's keys through its remapping") {
  StateMachine* sm = nullptr;
  auto result = runOne(
      {.outcomes = {"done"}, .input_keys = {"in"}, .output_keys = {"out"}},
      [](UserData& ud) {
        ud.set("out", ud.get<double>("in") * 2);
        return "done";
      },
      {{"in", "a"}, {"out", "b"}}, {{"a", 21.0}}, &sm);
  REQUIRE(result.ok());
  CHECK(sm->userdata().get<double>("b") == 42.0);
  CHECK_FALSE(sm->userdata().contains("out"));
}

TEST_CASE("undeclared keys are errors naming the state and the key") {
  auto read = runOne({.outcomes = {"done"}, .input_keys = {"a", "b"}}, [](UserData& ud) {
    ud.get<int>("x");
    return "done";
  });
  CHECK(read.outcome == "aborted");
  CHECK(read.error == "state `FOO` reads undeclared userdata key `x` (input keys: `a`, `b`)");

  auto write = runOne({.outcomes = {"done"}}, [](UserData& ud) {
    ud.set("y", 1);
    return "done";
  });
  CHECK(write.error == "state `FOO` writes undeclared userdata key `y` (output keys: none)");

  auto output_only = runOne({.outcomes = {"done"}, .output_keys = {"y"}}, [](UserData& ud) {
    ud.get<int>("y");
    return "done";
  });
  CHECK(output_only.error == "state `FOO` reads undeclared userdata key `y` (input keys: none)");
}

TEST_CASE("missing and mistyped keys name the state") {
  auto missing = runOne({.outcomes = {"done"}, .input_keys = {"x"}},
                        [](UserData& ud) {
                          ud.get<double>("x");
                          return "done";
                        },
                        {{"x", "speed"}});
  CHECK(missing.error ==
        "state `FOO` reads userdata key `x` (remapped to `speed`), which is not set");

  auto mistyped = runOne({.outcomes = {"done"}, .input_keys = {"x"}},
                         [](UserData& ud) {
                           ud.get<double>("x");
                           return "done";
                         },
                         {}, {{"x", "fast"}});
  CHECK(mistyped.error == "state `FOO` reads userdata key `x` as a double, but it holds a string");
}

TEST_CASE("nested containers copy their declared keys in and out") {
  StateMachine root({.outcomes = {"done"}, .userdata = {{"n", 1}, {"hidden", 5}}});
  auto& sub = root.add("SUB",
                       std::make_unique<StateMachine>(rt::StateMachineSpec{
                           .outcomes = {"done"}, .input_keys = {"n"}, .output_keys = {"m"}}),
                       {}, {{"m", "result"}});
  sub.add("INC", std::make_unique<LambdaState>(
                     StateSpec{.outcomes = {"done"}, .input_keys = {"n"}, .output_keys = {"m"}},
                     [](UserData& ud) {
                       ud.set("m", ud.get<int64_t>("n") + 1);
                       return "done";
                     }));
  sub.add("PEEK", std::make_unique<LambdaState>(
                      StateSpec{.outcomes = {"done"}, .input_keys = {"hidden"}},
                      [](UserData& ud) { return ud.find("hidden") ? "wrong" : "done"; }));
  auto result = rt::run(root);
  REQUIRE(result.ok());
  CHECK(result.outcome == "done");
  CHECK(root.userdata().get<int64_t>("result") == 2);
  CHECK(sub.userdata().get<int64_t>("n") == 1);
}

TEST_CASE("container userdata is set at construction and kept across runs") {
  StateMachine sm({.outcomes = {"done"}, .userdata = {{"count", 0}}});
  sm.add("INC",
         std::make_unique<rt::CallbacksState>(
             StateSpec{.input_keys = {"count"}},
             rt::Callbacks{
                 {"count", [](UserData& ud) -> Value { return ud.get<int64_t>("count") + 1; }}}),
         {{"succeeded", "done"}});
  CHECK(rt::run(sm).outcome == "done");
  CHECK(rt::run(sm).outcome == "done");
  CHECK(sm.userdata().get<int64_t>("count") == 2);
}

TEST_CASE("the root reads its input keys from the scope given to run") {
  StateMachine sm({.outcomes = {"done"}, .input_keys = {"x"}, .output_keys = {"y"}});
  sm.add("DOUBLE", std::make_unique<LambdaState>(
                       StateSpec{.outcomes = {"done"}, .input_keys = {"x"}, .output_keys = {"y"}},
                       [](UserData& ud) {
                         ud.set("y", ud.get<double>("x") * 2);
                         return "done";
                       }));
  rt::UserDataStore outside(rt::Map{{"x", 1.25}});
  REQUIRE(rt::run(sm, &outside).ok());
  CHECK(outside.get<double>("y") == 2.5);
}

TEST_CASE("a view sees keys set after its first read, and writes others see") {
  rt::UserDataStore store;
  auto state = std::make_unique<LambdaState>(
      StateSpec{.outcomes = {"done"}, .input_keys = {"x", "y"}, .output_keys = {"y"}},
      [](UserData&) { return "done"; });
  rt::Remapping remapping{{"y", "parent_y"}};
  UserData view(store, *state, &remapping);
  CHECK_FALSE(view.find("x"));  // resolved while unset
  store.set("x", 1);
  CHECK(view.get<int64_t>("x") == 1);
  store.set("x", "two");
  CHECK(view.get<std::string>("x") == "two");
  view.set("y", 3.5);
  CHECK(store.get<double>("parent_y") == 3.5);
  CHECK(view.get<double>("y") == 3.5);
  store.set("parent_y", 4.5);
  CHECK(view.get<double>("y") == 4.5);
  CHECK_THROWS_WITH_AS(view.set("x", 1),
                       "state `root` writes undeclared userdata key `x` (output keys: `y`)",
                       rt::UserDataError);
  CHECK_THROWS_WITH_AS(view.set("x", 1),  // still checked once resolved for reading
                       "state `root` writes undeclared userdata key `x` (output keys: `y`)",
                       rt::UserDataError);
}

TEST_CASE("at() by position is the entry itself in a machine's scope, a copy in a shared one") {
  auto state = std::make_unique<LambdaState>(StateSpec{.outcomes = {"done"}, .input_keys = {"x"}},
                                             [](UserData&) { return "done"; });
  rt::UserDataStore own;
  own.setShared(false);
  own.set("x", 1);
  UserData own_view(own, *state);
  const Value& entry = own_view.at("x", 0);
  own.set("x", 2);
  CHECK(entry.as<int64_t>() == 2);  // the store's entry, which the write changed
  rt::UserDataStore shared;
  shared.set("x", 1);
  UserData shared_view(shared, *state);
  const Value& copy = shared_view.at("x", 0);
  shared.set("x", 2);
  CHECK(copy.as<int64_t>() == 1);  // the view's copy, until the next read of `x`
  CHECK(shared_view.at("x", 0).as<int64_t>() == 2);
  CHECK(shared_view.at("x", 5).as<int64_t>() == 2);  // a wrong position: searched for
}

TEST_CASE("reads and writes by position") {
  auto state = std::make_unique<LambdaState>(
      StateSpec{.outcomes = {"done"}, .input_keys = {"x", "y"}, .output_keys = {"y"}},
      [](UserData&) { return "done"; });
  for (bool shared : {false, true}) {
    rt::UserDataStore store;
    store.setShared(shared);
    rt::Remapping remapping{{"y", "parent_y"}};
    UserData view(store, *state, &remapping);
    CHECK(view.findInput(1) == nullptr);  // not set yet
    view.setOutput(0, Value(1));
    REQUIRE(view.findInput(1) != nullptr);
    CHECK(*view.findInput(1) == Value(1));
    const Value kept(1.0);
    view.setOutput(0, kept);  // equal in Python, but another type: written
    CHECK(store.at("parent_y").type() == rt::ValueType::Double);
    CHECK_THROWS_WITH_AS(view.setOutput(1, Value(2)),
                         "state `root` has no output key at position 1 (output keys: `y`)",
                         rt::UserDataError);
    CHECK_THROWS_WITH_AS(view.findInput(2),
                         "state `root` has no input key at position 2 (input keys: `x`, `y`)",
                         rt::UserDataError);
  }
}
