// passes/optimize: each transform's IR before and after, that it is idempotent, that the IR
// stays well formed, and that the checks find nothing new afterwards.
#include <doctest/doctest.h>

#include <set>
#include <string>

#include "ir/verify.h"
#include "passes/optimize/transforms.h"
#include "passes/validate/checks.h"
#include "tests/unit/passes/compile.h"

namespace smachac::passes {
namespace {

void runChecks(testing::Compiled& c) {
  PassContext context = c.context();
  for (CheckFn check : {checkNames, checkTransitions, checkConcurrence, checkReachability,
                        checkUserdataFlow, checkUserdataUsage, checkUserdataTypes}) {
    check(*c.module, context);
  }
}

/// Runs `fn` on `script`; checks the IR before and after, idempotence, well-formedness, and
/// that the checks find no new kind of problem afterwards.
void expectTransform(TransformFn fn, const std::string& script, const std::string& before,
                     const std::string& after) {
  auto c = testing::lower(script);
  CHECK(c->ir() == before);
  runChecks(*c);
  std::vector<std::string> kinds = c->kinds();
  std::set<std::string> kinds_before(kinds.begin(), kinds.end());
  PassContext context = c->context();
  CHECK(fn(*c->module, context));
  CHECK(c->ir() == after);
  CHECK_FALSE(ir::verify(*c->module).has_value());
  CHECK_FALSE(fn(*c->module, context));
  auto fresh = testing::lower(script);  // the same diagnostics emitter is not reusable
  *fresh->module = *c->module;
  runChecks(*fresh);
  for (const std::string& kind : fresh->kinds()) CHECK(kinds_before.contains(kind));
}

TEST_CASE("prune-unreachable-states removes states and keeps their effective userdata") {
  expectTransform(pruneUnreachableStates, R"(name: p
template: Base
outcomes: [done]
userdata: {speed: 1}
states:
  - A: {template: T, outcomes: [ok], userdata: {tool: a}, input_keys: [speed, tool],
        transitions: {ok: done}}
  - B: {template: T, outcomes: [ok], userdata: {speed: 2, tool: b}, transitions: {ok: C}}
  - C: {template: T, outcomes: [ok], userdata: {tool: c}, transitions: {ok: A}}
  - D:
      template: StateMachine
      outcomes: [x]
      transitions: {x: A}
      states:
        - IN: {template: T, outcomes: [x]}
)",
                  R"(base p template=Base @1:1
  outcomes: [done]
  userdata:
    speed: int = 1
  leaf A template=T @6:8
    outcomes: [ok]
    input_keys: [speed, tool]
    userdata:
      tool: string = "a"
    transitions:
      ok -> done (outcome)
  leaf B template=T @8:8
    outcomes: [ok]
    userdata:
      speed: int = 2
      tool: string = "b"
    transitions:
      ok -> C (state)
  leaf C template=T @9:8
    outcomes: [ok]
    userdata:
      tool: string = "c"
    transitions:
      ok -> A (state)
  state_machine D template=StateMachine @11:7
    outcomes: [x]
    transitions:
      x -> A (state)
    leaf IN template=T @15:15
      outcomes: [x]
)",
                  R"(base p template=Base @1:1
  outcomes: [done]
  userdata:
    speed: int = 2
    tool: string = "c"
  leaf A template=T @6:8
    outcomes: [ok]
    input_keys: [speed, tool]
    transitions:
      ok -> done (outcome)
)");
}

TEST_CASE("dedupe-userdata removes entries equal to the value in effect") {
  expectTransform(dedupeUserdata, R"(name: d
template: Base
outcomes: [done]
userdata: {speed: 0.5}
states:
  - A: {template: T, outcomes: [ok], userdata: {speed: 0.5, tool: x}, input_keys: [speed, tool],
        transitions: {ok: B}}
  - B: {template: T, outcomes: [ok], userdata: {tool: x}, transitions: {ok: C}}
  - C: {template: T, outcomes: [ok], userdata: {tool: y}, transitions: {ok: E}}
  - E: {template: T, outcomes: [ok], userdata: {tool: x}, transitions: {ok: done}}
)",
                  R"(base d template=Base @1:1
  outcomes: [done]
  userdata:
    speed: float = 0.5
  leaf A template=T @6:8
    outcomes: [ok]
    input_keys: [speed, tool]
    userdata:
      speed: float = 0.5
      tool: string = "x"
    transitions:
      ok -> B (state)
  leaf B template=T @8:8
    outcomes: [ok]
    userdata:
      tool: string = "x"
    transitions:
      ok -> C (state)
  leaf C template=T @9:8
    outcomes: [ok]
    userdata:
      tool: string = "y"
    transitions:
      ok -> E (state)
  leaf E template=T @10:8
    outcomes: [ok]
    userdata:
      tool: string = "x"
    transitions:
      ok -> done (outcome)
)",
                  R"(base d template=Base @1:1
  outcomes: [done]
  userdata:
    speed: float = 0.5
  leaf A template=T @6:8
    outcomes: [ok]
    input_keys: [speed, tool]
    userdata:
      tool: string = "x"
    transitions:
      ok -> B (state)
  leaf B template=T @8:8
    outcomes: [ok]
    transitions:
      ok -> C (state)
  leaf C template=T @9:8
    outcomes: [ok]
    userdata:
      tool: string = "y"
    transitions:
      ok -> E (state)
  leaf E template=T @10:8
    outcomes: [ok]
    userdata:
      tool: string = "x"
    transitions:
      ok -> done (outcome)
)");
}

TEST_CASE("fold-trivial-containers folds nested pass-through containers into their state") {
  expectTransform(foldTrivialContainers, R"(name: f
template: Base
outcomes: [done, failed]
userdata: {goal: 1}
states:
  - OUTER:
      template: StateMachine
      outcomes: [ok, bad]
      input_keys: [target]
      output_keys: [result]
      remapping: {target: goal, result: log}
      transitions: {ok: NEXT, bad: failed}
      states:
        - INNER:
            template: StateMachine
            outcomes: [ok, bad]
            input_keys: [target]
            output_keys: [result]
            transitions: {ok: ok, bad: bad}
            states:
              - MOVE:
                  template: MoveState
                  outcomes: [succeeded, aborted, bad]
                  input_keys: [pose]
                  output_keys: [result]
                  remapping: {pose: target}
                  transitions: {succeeded: ok, aborted: bad}
  - NEXT: {template: T, outcomes: [ok], input_keys: [log], transitions: {ok: OUTER}}
)",
                  R"(base f template=Base @1:1
  outcomes: [done, failed]
  userdata:
    goal: int = 1
  state_machine OUTER template=StateMachine @7:7
    outcomes: [ok, bad]
    input_keys: [target]
    output_keys: [result]
    remapping:
      target <- goal
      result <- log
    transitions:
      ok -> NEXT (state)
      bad -> failed (outcome)
    state_machine INNER template=StateMachine @15:13
      outcomes: [ok, bad]
      input_keys: [target]
      output_keys: [result]
      transitions:
        ok -> ok (outcome)
        bad -> bad (outcome)
      leaf MOVE template=MoveState @22:19
        outcomes: [succeeded, aborted, bad]
        input_keys: [pose]
        output_keys: [result]
        remapping:
          pose <- target
        transitions:
          succeeded -> ok (outcome)
          aborted -> bad (outcome)
  leaf NEXT template=T @28:11
    outcomes: [ok]
    input_keys: [log]
    transitions:
      ok -> OUTER (state)
)",
                  R"(base f template=Base @1:1
  outcomes: [done, failed]
  userdata:
    goal: int = 1
  leaf OUTER template=MoveState @22:19
    outcomes: [succeeded, aborted, bad]
    input_keys: [pose]
    output_keys: [result]
    remapping:
      pose <- goal
      result <- log
    transitions:
      succeeded -> NEXT (state)
      aborted -> failed (outcome)
      bad -> failed (outcome)
  leaf NEXT template=T @28:11
    outcomes: [ok]
    input_keys: [log]
    transitions:
      ok -> OUTER (state)
)");
}

TEST_CASE("fold-trivial-containers leaves containers that are not pass-through alone") {
  const char* scripts[] = {
      // two states
      "name: f\ntemplate: Base\noutcomes: [done]\nstates:\n  - S:\n      template: StateMachine\n"
      "      outcomes: [done]\n      transitions: {done: done}\n      states:\n"
      "        - A: {template: T, outcomes: [ok], transitions: {ok: B}}\n"
      "        - B: {template: T, outcomes: [ok], transitions: {ok: done}}\n",
      // the leaf's userdata lives in the container's scope
      "name: f\ntemplate: Base\noutcomes: [done]\nstates:\n  - S:\n      template: StateMachine\n"
      "      outcomes: [done]\n      transitions: {done: done}\n      states:\n"
      "        - A: {template: T, outcomes: [ok], userdata: {x: 1}, transitions: {ok: done}}\n",
      // the leaf reads a key the container defines itself
      "name: f\ntemplate: Base\noutcomes: [done]\nstates:\n  - S:\n      template: StateMachine\n"
      "      outcomes: [done]\n      userdata: {x: 1}\n      transitions: {done: done}\n"
      "      states:\n"
      "        - A: {template: T, outcomes: [ok], input_keys: [x], transitions: {ok: done}}\n",
      // outcomes unknown
      "name: f\ntemplate: Base\noutcomes: [done]\nstates:\n  - S:\n      template: StateMachine\n"
      "      outcomes: [done]\n      transitions: {done: done}\n      states:\n"
      "        - A: {template: T, transitions: {ok: done}}\n",
      // a custom container template
      "name: f\ntemplate: Base\noutcomes: [done]\nstates:\n  - S:\n      template: MySM\n"
      "      outcomes: [done]\n      transitions: {done: done}\n      states:\n"
      "        - A: {template: T, outcomes: [ok], transitions: {ok: done}}\n",
  };
  for (const char* script : scripts) {
    auto c = testing::lower(script);
    std::string before = c->ir();
    PassContext context = c->context();
    CHECK_FALSE(foldTrivialContainers(*c->module, context));
    CHECK(c->ir() == before);
  }
}

}  // namespace
}  // namespace smachac::passes
