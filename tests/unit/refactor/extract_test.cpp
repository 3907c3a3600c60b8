// extract on small scripts.
#include <doctest/doctest.h>

#include "tests/unit/refactor/scripts.h"

namespace smachac::refactor {

using testing::TempDir;

TEST_CASE("extract: caller keys stay, the rest becomes a one-state sub-script") {
  TempDir dir;
  std::string path = dir.write("s.yml", R"(# header
name: sm
template: Base
outcomes: [done]
states:
  - X:
      template: Step
      params: {p: 1}
      value: [params, p]
      transitions: {succeeded: done}
)");
  std::unique_ptr<testing::Loaded> loaded = testing::load(path);
  REQUIRE(loaded->script);
  std::optional<ExtractResult> result = extract(*loaded->script, "X", "x_sub", loaded->diags);
  REQUIRE(result);
  CHECK(result->sub_script == "- X:\n    template: Step\n    value: [params, p]\n");
  CHECK(result->super_script ==
        "# header\nname: sm\ntemplate: Base\noutcomes: [done]\nstates:\n  - X:\n"
        "      script: x_sub\n      params: {p: 1}\n      transitions: {succeeded: done}\n");
  dir.write("x_sub.yml", result->sub_script);
  testing::LintResult lint = testing::lint(dir.write("super.yml", result->super_script));
  CHECK(lint.errors == 0);
  CHECK(lint.warnings == 0);
}

TEST_CASE("extract: an unknown state is an error, never the last state") {
  TempDir dir;
  std::string path = dir.write("s.yml", "name: sm\ntemplate: Base\nstates:\n- A: {template: T}\n");
  std::unique_ptr<testing::Loaded> loaded = testing::load(path);
  REQUIRE(loaded->script);
  CHECK_FALSE(extract(*loaded->script, "B", "b", loaded->diags));
  CHECK(loaded->kinds() == std::vector<std::string>{"unknown-root-state"});
}

}  // namespace smachac::refactor
