// Params inheritance, lookups and string constructs, as SMACHA resolves them.
#include <doctest/doctest.h>

#include "frontend/lookups.h"
#include "ir/value_text.h"

using smachac::ir::Value;

namespace {

Value str(const char* s) { return Value::string(s); }
Value list(std::initializer_list<Value> items) { return Value::list(items); }

std::string resolved(Value vars, std::optional<Value> inherited = std::nullopt) {
  smachac::DiagnosticEmitter diags;
  smachac::frontend::inheritParams(vars, inherited);
  smachac::frontend::resolveLookups(vars, diags);
  std::string out = smachac::ir::formatValue(vars);
  for (const auto& d : diags.diagnostics()) out += " | " + d.message;
  return out;
}

}  // namespace

TEST_CASE("own params win over inherited ones") {
  Value inherited = Value::map({{"a", {}, Value::integer(1)}, {"b", {}, Value::integer(2)}});
  Value vars = Value::map({{"params", {}, Value::map({{"b", {}, Value::integer(5)}})}});
  CHECK(resolved(vars, inherited) == "{params: {b: 5, a: 1}}");
  CHECK(resolved(Value::map({}), inherited) == "{params: {a: 1, b: 2}}");
}

TEST_CASE("lookups against any key, in order") {
  Value vars = Value::map({{"params", {}, Value::map({{"n", {}, str("FOO")}})},
                           {"x", {}, list({list({str("n")})})},
                           {"y", {}, list({str("x")})},
                           {"z", {}, list({list({str("params"), str("n")}), str("_1")})},
                           {"w", {}, list({str("a"), str("b")})}});
  CHECK(resolved(vars) ==
        "{params: {n: \"FOO\"}, x: \"FOO\", y: \"FOO\", z: \"FOO_1\", w: [\"a\", \"b\"]}");
}

TEST_CASE("mapping values are resolved one level deep") {
  Value vars =
      Value::map({{"params", {}, Value::map({{"v", {}, Value::real(0.5)}})},
                  {"userdata",
                   {},
                   Value::map({{"speed", {}, list({list({str("v")})})},
                               {"deep", {}, Value::map({{"k", {}, list({list({str("v")})})}})}})}});
  CHECK(resolved(vars) == "{params: {v: 0.5}, userdata: {speed: 0.5, deep: {k: [[\"v\"]]}}}");
}

TEST_CASE("constructs print parts like Python str()") {
  Value vars =
      Value::map({{"params", {}, Value::map({{"b", {}, Value::boolean(true)}})},
                  {"s", {}, list({str("flag="), list({list({str("b")})}), Value::integer(3)})},
                  {"cb", {}, list({str("`f("), list({list({str("b")})}), str(")`")})}});
  CHECK(resolved(vars) == "{params: {b: true}, s: \"flag=True3\", cb: `f(True)`}");
}

TEST_CASE("a failed params lookup is an error") {
  Value vars = Value::map(
      {{"params", {}, Value::map({})}, {"x", {}, list({str("params"), str("missing")})}});
  CHECK(resolved(vars) ==
        "{params: {}, x: [\"params\", \"missing\"]} | lookup `[params, missing]` does not "
        "resolve: `params` has no `missing`");
}
