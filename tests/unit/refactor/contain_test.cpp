// contain on small scripts: outcomes, params, userdata and key inference.
#include <doctest/doctest.h>

#include "tests/unit/refactor/scripts.h"

namespace smachac::refactor {
namespace {

using testing::containFile;
using testing::TempDir;

const char* const kSequence = R"(name: sm
template: Base
outcomes: [done, failed]
states:
- A:
    template: Step
    transitions: {succeeded: B, aborted: failed}
- B:
    template: Step
    transitions: {succeeded: C, aborted: failed}
- C:
    template: Step
    transitions: {succeeded: done}
)";

ContainRequest request(std::vector<std::string> states,
                       ir::StateKind kind = ir::StateKind::StateMachine) {
  return {"SUB", kind, std::move(states), {}};
}

}  // namespace

TEST_CASE("contain: one outcome per distinct external target, inner transitions rewritten") {
  TempDir dir;
  std::optional<std::string> out = containFile(dir.write("s.yml", kSequence), request({"A", "B"}));
  REQUIRE(out);
  CHECK(out->find("    outcomes: [sub_outcome_1, sub_outcome_2]\n"
                  "    transitions: {sub_outcome_1: failed, sub_outcome_2: C}\n") !=
        std::string::npos);
  CHECK(out->find("transitions: {succeeded: B, aborted: sub_outcome_1}") != std::string::npos);
  CHECK(out->find("transitions: {succeeded: sub_outcome_2, aborted: sub_outcome_1}") !=
        std::string::npos);
}

TEST_CASE("contain: a Concurrence's default outcome goes to the first external target") {
  TempDir dir;
  std::optional<std::string> out =
      containFile(dir.write("s.yml", kSequence), request({"B", "C"}, ir::StateKind::Concurrence));
  REQUIRE(out);
  CHECK(out->find("transitions: {succeeded: SUB, aborted: failed}") != std::string::npos);
  CHECK(out->find("outcome_map: {sub_outcome_1: {B: aborted}, sub_outcome_2: {B: succeeded, "
                  "C: succeeded}}") != std::string::npos);
  CHECK(out->find("sub_default_outcome: failed}") != std::string::npos);
  CHECK(out->find("transitions: {succeeded: C") == std::string::npos);  // children's deleted
}

TEST_CASE("contain: --default-target overrides the default outcome's transition") {
  TempDir dir;
  ContainRequest r = request({"A", "B"}, ir::StateKind::Concurrence);
  r.default_target = "C";
  std::optional<std::string> out = containFile(dir.write("s.yml", kSequence), r);
  REQUIRE(out);
  CHECK(out->find("sub_default_outcome: C}") != std::string::npos);
}

TEST_CASE("contain: selection and name errors") {
  TempDir dir;
  std::string path = dir.write("s.yml", kSequence);
  std::vector<std::string> kinds;
  CHECK_FALSE(containFile(path, request({"A", "C"}), &kinds));
  CHECK(kinds == std::vector<std::string>{"selection-not-consecutive"});
  CHECK_FALSE(containFile(path, request({"X"}), &kinds));
  CHECK(kinds == std::vector<std::string>{"unknown-root-state"});
  ContainRequest taken = request({"A"});
  taken.name = "C";
  CHECK_FALSE(containFile(path, taken, &kinds));
  CHECK(kinds == std::vector<std::string>{"container-name-taken"});
  ContainRequest bad_target = request({"A"}, ir::StateKind::Concurrence);
  bad_target.default_target = "nowhere";
  CHECK_FALSE(containFile(path, bad_target, &kinds));
  CHECK(kinds == std::vector<std::string>{"unknown-default-target"});
}

TEST_CASE("contain: params clash renamed, lookups below a state's own param kept") {
  TempDir dir;
  std::string path = dir.write("s.yml", R"(name: sm
template: Base
outcomes: [done]
states:
- A:
    template: Step
    params: {x: 1}
    value: [params, x]
    transitions: {succeeded: B}
- B:
    template: StateMachine
    params: {x: 2}
    outcomes: [finished]
    transitions: {finished: done}
    states:
    - B1:
        template: Step
        value: [[x]]
        transitions: {succeeded: B2}
    - B2:
        template: Step
        params: {x: 3}
        value: [[x]]
        transitions: {succeeded: finished}
)");
  std::optional<std::string> out = containFile(path, request({"A", "B"}));
  REQUIRE(out);
  CHECK(out->find("params: {x: 1, x_1: 2}") != std::string::npos);
  CHECK(out->find("value: [params, x]\n") != std::string::npos);
  CHECK(out->find("            value: [[x_1]]\n") != std::string::npos);
  CHECK(out->find("            params: {x: 3}\n            value: [[x]]\n") != std::string::npos);
}

TEST_CASE("contain: keys written on only one path into a reader are input keys") {
  TempDir dir;
  std::string path = dir.write("s.yml", R"(name: sm
template: Base
outcomes: [done]
states:
- INIT:
    template: Init
    output_keys: [x]
    transitions: {succeeded: CHOOSE}
- CHOOSE:
    template: Choose
    transitions: {left: WRITE, right: READ}
- WRITE:
    template: Write
    output_keys: [x, y]
    transitions: {succeeded: READ}
- READ:
    template: Read
    input_keys: [x]
    output_keys: [z]
    transitions: {succeeded: USE}
- USE:
    template: Use
    input_keys: [z, y]
    outcomes: [done]
)");
  std::optional<std::string> out = containFile(path, request({"CHOOSE", "WRITE", "READ"}));
  REQUIRE(out);
  CHECK(out->find("input_keys: [x]\n    output_keys: [y, z]\n") != std::string::npos);
  CHECK(testing::lint(dir.write("out.yml", *out)).errors == 0);
}

TEST_CASE("contain: userdata moves to the root, an existing root userdata map grows") {
  TempDir dir;
  std::string path = dir.write("s.yml", R"(name: sm
template: Base
outcomes: [done]
userdata:
  a: 1
states:
- S:
    template: Use
    userdata:
      b: [1, 2]
      c: 'x'
    input_keys: [a, b, c]
    transitions: {succeeded: done}
)");
  std::optional<std::string> out = containFile(path, request({"S"}));
  REQUIRE(out);
  CHECK(out->find("userdata:\n  a: 1\n  b: [1, 2]\n  c: 'x'\nstates:\n") != std::string::npos);
  CHECK(out->find("    input_keys: [a, b, c]\n") != std::string::npos);
  testing::LintResult lint = testing::lint(dir.write("out.yml", *out));
  CHECK(lint.errors == 0);
  CHECK(lint.warnings == 0);
}

}  // namespace smachac::refactor
