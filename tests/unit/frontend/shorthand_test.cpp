// Shorthand expansion applies to the keys of one mapping only.
#include <doctest/doctest.h>

#include "frontend/shorthand.h"
#include "ir/value_text.h"

using smachac::ir::Value;

TEST_CASE("keys are expanded in place, values untouched") {
  Value transitions = Value::map({{"ok", {}, Value::string("t")}});
  Value state = Value::map(
      {{"T", {}, Value::string("S")}, {"t", {}, transitions}, {"custom", {}, Value::integer(1)}});
  smachac::DiagnosticEmitter diags;
  smachac::frontend::expandShorthand(state, diags);
  CHECK(smachac::ir::formatValue(state) ==
        "{template: \"S\", transitions: {ok: \"t\"}, custom: 1}");
  CHECK_FALSE(diags.hasErrors());
}

TEST_CASE("a shorthand next to its longhand is an error") {
  Value state = Value::map({{"o", {}, Value::list({})}, {"outcomes", {}, Value::list({})}});
  smachac::DiagnosticEmitter diags;
  smachac::frontend::expandShorthand(state, diags);
  REQUIRE(diags.diagnostics().size() == 1);
  CHECK(diags.diagnostics()[0].message == "`o` is shorthand for `outcomes`, which is also given");
  CHECK(smachac::frontend::longhandOf("cb") == "callbacks");
  CHECK_FALSE(smachac::frontend::longhandOf("callbacks").has_value());
}
