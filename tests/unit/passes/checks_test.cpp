// passes/validate: behaviour of the checks beyond their golden tests (tests/golden/validate),
// in particular what they must not report.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "passes/validate/checks.h"
#include "tests/unit/passes/compile.h"

namespace smachac::passes {
namespace {

using testing::check;
using Kinds = std::vector<std::string>;

TEST_CASE("check-transitions: every problem in every container is reported") {
  auto c = check(R"(
name: t
template: Base
outcomes: [done, spare]
states:
  - A: {template: T, outcomes: [ok, bad], transitions: {ok: B, oops: done}}
  - B:
      template: StateMachine
      outcomes: [fine]
      transitions: {fine: done}
      states:
        - IN: {template: T, outcomes: [ok], transitions: {ok: fnie}}
)",
                 checkTransitions);
  CHECK(c->located() == std::vector<std::string>{"6:64 undeclared-outcome", "6:37 unmapped-outcome",
                                                 "4:18 unused-container-outcome",
                                                 "12:63 unknown-transition-target"});
  CHECK(c->diags.diagnostics().back().message ==
        "transition target `fnie` is not a state in `B`; did you mean `fine`?");
}

TEST_CASE("check-transitions: pass-through outcomes and unknown outcomes are not errors") {
  auto c = check(R"(
name: t
template: Base
outcomes: [done, aborted]
states:
  - A: {template: T, outcomes: [ok, aborted], transitions: {ok: B}}
  - B: {template: T, transitions: {succeeded: done}}
)",
                 checkTransitions);
  CHECK(c->kinds().empty());
}

TEST_CASE("check-names: identifiers only matter for code targets") {
  const char* script = R"(
name: t
template: Base
outcomes: [done]
userdata: {my-key: 1}
states:
  - MY SM:
      template: StateMachine
      outcomes: [done]
      transitions: {done: done}
      states:
        - A LEAF: {template: T, outcomes: [done]}
)";
  CHECK(check(script, checkNames, "ir")->kinds().empty());
  CHECK(check(script, checkNames, "json")->kinds().empty());
  CHECK(check(script, checkNames, "smach")->kinds() ==
        Kinds{"invalid-identifier", "invalid-identifier"});
  CHECK(check(script, checkNames, "cpp")->kinds() ==
        Kinds{"invalid-identifier", "invalid-identifier"});
}

/// A Concurrence C with children X (outcomes ok, no) and Y, and the given outcome_map.
std::string concurrence(const std::string& outcome_map) {
  return "name: t\ntemplate: Base\noutcomes: [done]\nstates:\n  - C:\n"
         "      template: Concurrence\n      outcomes: [a, b, d]\n      default_outcome: d\n"
         "      outcome_map:\n" +
         outcome_map +
         "      transitions: {a: done, b: done, d: done}\n      states:\n"
         "        - X: {template: T, outcomes: [ok, no]}\n        - Y: {template: T}\n";
}

TEST_CASE("check-concurrence: a larger entry before its subset is chosen by SMACH 2.5") {
  // Sorted, `a` (X and Y) comes before `b` (X only): SMACH 2.5 chooses `a`, older SMACH `b`.
  // Neither is reported as never chosen.
  auto c = check(concurrence("        b: {X: ok}\n        a: {X: ok, Y: ok}\n"), checkConcurrence);
  CHECK(c->located() == std::vector<std::string>{"11:9 version-dependent-outcome-map"});
  // The larger entry last: every version chooses it.
  c = check(concurrence("        a: {X: ok}\n        b: {X: ok, Y: whatever}\n"), checkConcurrence);
  CHECK(c->kinds().empty());
}

TEST_CASE("check-concurrence: entries that cannot hold together are not compared") {
  auto c =
      check(concurrence("        a: {X: ok}\n        b: {X: no, Y: done}\n"), checkConcurrence);
  CHECK(c->kinds().empty());
  c = check(concurrence("        a: {X: ok, Y: done}\n        b: {X: no}\n"), checkConcurrence);
  CHECK(c->kinds().empty());
}

TEST_CASE("check-concurrence: equally large entries that can hold together differ by version") {
  auto c = check(concurrence("        b: {Y: done}\n        a: {X: ok}\n"), checkConcurrence);
  CHECK(c->located() == std::vector<std::string>{"11:9 version-dependent-outcome-map"});
}

TEST_CASE("check-concurrence: entries SMACH 2.5 never chooses") {
  // The same conditions: the later entry is never chosen; no second warning for the pair.
  auto c = check(concurrence("        a: {X: ok}\n        b: {X: ok}\n"), checkConcurrence);
  CHECK(c->located() == std::vector<std::string>{"11:9 shadowed-outcome-map-entry"});
  // No conditions: never chosen, wherever it stands.
  c = check(concurrence("        a: {}\n        b: {X: ok}\n"), checkConcurrence);
  CHECK(c->located() == std::vector<std::string>{"10:9 shadowed-outcome-map-entry"});
  c = check(concurrence("        b: {}\n        a: {X: ok}\n"), checkConcurrence);
  CHECK(c->located() == std::vector<std::string>{"10:9 shadowed-outcome-map-entry"});
}

TEST_CASE("check-concurrence: `preempted` is an outcome a preempted concurrence ends with") {
  // SMACH 2.5 returns it when every child serviced the preempt request; `d` stays unused.
  std::string script = concurrence("        a: {X: ok}\n        b: {X: no}\n");
  script.replace(script.find("[a, b, d]"), 9, "[a, b, preempted, d]");
  script.replace(script.find("d: done}"), 8, "d: done, preempted: done}");
  auto c = check(script, checkConcurrence);
  CHECK(c->kinds().empty());
}

TEST_CASE("check-reachability: no cascade from a container that never finishes") {
  auto c = check(R"(
name: t
template: Base
outcomes: [done]
states:
  - SUB:
      template: StateMachine
      outcomes: [out]
      transitions: {out: NEXT}
      states:
        - SPIN: {template: T, outcomes: [again], transitions: {again: SPIN}}
  - NEXT: {template: T, outcomes: [ok], transitions: {ok: done}}
)",
                 checkReachability);
  CHECK(c->located() == std::vector<std::string>{"6:5 container-never-finishes"});
}

TEST_CASE("check-userdata-flow: leaf userdata is set before any state runs") {
  // SMACHA renders LATER's userdata into the root when the root is built, so EARLY can read
  // it even though EARLY runs first.
  auto c = check(R"(
name: t
template: Base
outcomes: [done]
states:
  - EARLY: {template: T, outcomes: [ok], input_keys: [x], transitions: {ok: LATER}}
  - LATER: {template: T, outcomes: [ok], userdata: {x: 1}, transitions: {ok: done}}
)",
                 checkUserdataFlow);
  CHECK(c->kinds().empty());
}

TEST_CASE("check-userdata-flow: keys cross containers only through their interface") {
  auto c = check(R"(
name: t
template: Base
outcomes: [done]
userdata: {x: 1, y: 2}
states:
  - SUB:
      template: StateMachine
      outcomes: [done]
      input_keys: [x]
      output_keys: [z]
      transitions: {done: USE}
      states:
        - IN: {template: T, outcomes: [ok], input_keys: [x, y], output_keys: [z],
               transitions: {ok: done}}
  - USE: {template: T, outcomes: [ok], input_keys: [z], transitions: {ok: done}}
)",
                 checkUserdataFlow);
  CHECK(c->located() == std::vector<std::string>{"14:61 undefined-userdata-key"});
  CHECK(c->diags.diagnostics()[0].notes.size() == 1);  // `t` has `y`
}

TEST_CASE("check-userdata-flow: a Concurrence's children cannot rely on each other") {
  auto c = check(R"(
name: t
template: Base
outcomes: [done]
states:
  - C:
      template: Concurrence
      outcomes: [done]
      default_outcome: done
      transitions: {done: done}
      states:
        - W: {template: T, output_keys: [x]}
        - R: {template: T, input_keys: [x]}
)",
                 checkUserdataFlow);
  CHECK(c->kinds() == Kinds{"maybe-undefined-userdata-key"});
}

TEST_CASE("check-userdata-usage: unused keys, on by default") {
  // x is read by nobody; y, written in the root scope, is a result of the script; z, written
  // in a container that does not output it, is unused.
  const char* script = R"(
name: t
template: Base
outcomes: [done]
userdata: {x: 1, w: 2}
states:
  - A: {template: T, outcomes: [ok], input_keys: [w], output_keys: [y], transitions: {ok: S}}
  - S:
      template: StateMachine
      outcomes: [fin]
      transitions: {fin: done}
      states:
        - B: {template: T, outcomes: [ok], input_keys: [v], output_keys: [z], transitions: {ok: fin}}
)";
  CHECK(check(script, checkUserdataUsage)->kinds() ==
        Kinds{"unused-userdata-key", "unused-userdata-key"});
  CHECK(check(script, checkUserdataUsage, "ir", {"-Wno-unused-userdata-key"})->kinds().empty());
  // A leaf without `input_keys` may read any key (its template declares them): no report.
  std::string unknown_reader = script;
  unknown_reader.replace(unknown_reader.find("input_keys: [w], "), 17, "");
  CHECK(check(unknown_reader, checkUserdataUsage)->kinds() == Kinds{"unused-userdata-key"});
}

TEST_CASE("check-userdata-types: int and float, null and expressions are compatible") {
  auto c = check(R"(
name: t
template: Base
outcomes: [done]
userdata: {a: 1.5, b: null, c: "`compute()`", d: [1, 2], e: {k: 1}}
states:
  - SUB:
      template: StateMachine
      outcomes: [done]
      input_keys: [a, b, c, d, e]
      userdata: {a: 1, b: text, c: 3, d: [0.5], e: {k: 2.5}}
      transitions: {done: done}
      states:
        - IN: {template: T, transitions: {ok: done}}
)",
                 checkUserdataTypes);
  CHECK(c->kinds().empty());
}

TEST_CASE("every check survives odd but valid IR") {
  const char* scripts[] = {
      "name: t\ntemplate: Base\nstates: []\n",
      "name: t\ntemplate: Base\nstates:\n  - A: {template: T}\n",
      "name: t\ntemplate: Base\noutcomes: []\nstates:\n  - A: {template: T, transitions: {a: A}}\n",
      "name: t\ntemplate: Base\nstates:\n  - C: {template: Concurrence, states: [],"
      " outcome_map: {x: {}}}\n",
      "name: t\ntemplate: Base\nstates:\n  - C: {template: Concurrence, outcomes: [x],"
      " default_outcome: x, outcome_map: {x: {}}, states: [{A: {template: T}}]}\n",
  };
  CheckFn checks[] = {checkNames,        checkTransitions,   checkConcurrence,  checkReachability,
                      checkUserdataFlow, checkUserdataUsage, checkUserdataTypes};
  for (const char* script : scripts) {
    for (CheckFn fn : checks) check(script, fn, "smach", {"-Wunused-userdata-key"});
  }
}

}  // namespace
}  // namespace smachac::passes
