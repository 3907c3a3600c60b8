// Rendering behaviours not covered by the differential suite: the Python 2 dict aliases,
// custom filters/tests/globals, values built in C++, YAML 1.2 contexts, list identity across
// renders and macro calls.
#include <doctest/doctest.h>

#include "backends/tmpl/values/value_print.h"
#include "tests/unit/backends/tmpl/tmpl_test_util.h"

using smachac::tmpl::CallArgs;
using smachac::tmpl::Value;
using smachac::tmpl::testing::context;
using smachac::tmpl::testing::makeEnv;
using smachac::tmpl::testing::render;
using smachac::tmpl::testing::renderError;

TEST_CASE("iteritems, iterkeys and itervalues are aliases (SMACHA's Utils uses iteritems)") {
  CHECK(render("{% for k, v in d.iteritems() %}{{ k }}={{ v }};{% endfor %}", "d: {b: 1, a: 2}") ==
        "b=1;a=2;");
  CHECK(render("{{ d.iterkeys() | list }} {{ d.itervalues() | list }}", "d: {x: 1}") ==
        "['x'] [1]");
}

TEST_CASE("custom filters, tests and globals can be registered") {
  auto env =
      makeEnv({{"t", "{{ 'a\"b' | cpp_string }} {{ 3 is small }} {{ 30 is small }} {{ answer }}"}});
  env->addFilter("cpp_string", [](const Value& in, const CallArgs&) {
    std::string out = "\"";
    for (char c : in.s()) out += c == '"' ? std::string("\\\"") : std::string(1, c);
    return Value::string(out + "\"");
  });
  env->addTest("small", [](const Value& in, const CallArgs&) { return in.isInt() && in.i() < 10; });
  env->addGlobal("answer", Value::integer(42));
  CHECK(env->render("t", Value::newDict()) == "\"a\\\"b\" True False 42");
}

TEST_CASE("custom filters raise located errors through fail()") {
  auto env = makeEnv({{"t", "\n  {{ 1 | picky }}"}});
  env->addFilter("picky",
                 [](const Value&, const CallArgs&) -> Value { smachac::tmpl::fail("too picky"); });
  CHECK_THROWS_WITH(env->render("t", Value::newDict()), "t:2:10: too picky");
}

TEST_CASE("contexts built in C++ render like Python values") {
  Value ctx = Value::newDict();
  ctx.dict().setString("rate", Value::real(100.0));
  ctx.dict().setString("keys", Value::newList({Value::string("a"), Value::string("b")}));
  auto env = makeEnv({{"t", "{{ rate }} {{ keys }} {{ keys | join(',') }}"}});
  CHECK(env->render("t", ctx) == "100.0 ['a', 'b'] a,b");
}

TEST_CASE("YAML contexts use the YAML 1.2 core schema") {
  CHECK(render("{{ [a, b, c, d, e, f, g, h, i] }}",
               "{a: yes, b: no, c: on, d: true, e: 'true', f: 0o17, g: 0x1F, h: 1_000, i: ~}") ==
        "['yes', 'no', 'on', True, 'true', 15, 31, '1_000', None]");
  CHECK(render("{{ [a, b, c, d] }}", "{a: 1.0, b: .5, c: 1e3, d: -.inf}") ==
        "[1.0, 0.5, 1000.0, -inf]");
  CHECK(render("{% for k in m %}{{ k }}{% endfor %}", "m: {z: 1, a: 2, m: 3}") == "zam");
  CHECK(render("{{ s }}|{{ n is string }}", "{s: '01', n: '5'}") == "01|True");
}

TEST_CASE("lists shared through the context are the same object across renders") {
  auto env = makeEnv(
      {{"t", "{% if 'x' not in seen %}first{% do seen.append('x') %}{% else %}again{% endif %}"}});
  Value ctx = Value::newDict();
  Value seen = Value::newList();
  ctx.dict().setString("seen", seen);
  CHECK(env->render("t", ctx) == "first");
  CHECK(env->render("t", ctx) == "again");
  CHECK(smachac::tmpl::str(seen) == "['x']");
}

TEST_CASE("lists passed to imported macros are mutated in place") {
  auto env = makeEnv(
      {{"main",
        "{% from 'lib' import mark %}{{ mark(h, 'a') }}{{ mark(h, 'a') }}{{ mark(h, 'b') }}"},
       {"lib",
        "{% macro mark(h, m) %}{% if m not in h %}+{{ m }}{% do h.append(m) %}{% endif %}{% "
        "endmacro %}"}});
  Value ctx = context("h: []");
  CHECK(env->render("main", ctx) == "+a+b");
  CHECK(smachac::tmpl::str(*ctx.dict().findString("h")) == "['a', 'b']");
}

TEST_CASE("top-level sets do not modify the caller's context dict") {
  auto env = makeEnv({{"t", "{% set x = 2 %}{{ x }}"}});
  Value ctx = context("x: 1");
  CHECK(env->render("t", ctx) == "2");
  CHECK(smachac::tmpl::str(*ctx.dict().findString("x")) == "1");
}

TEST_CASE("a loop object that escapes its loop stays usable") {
  CHECK(render("{% set keep = [] %}{% for x in [1, 2] %}{% do keep.append(loop) %}{% endfor %}"
               "{{ keep[0].length }} {{ keep[0].last }} {{ keep[1] }}") ==
        "2 True <LoopContext 2/2>");
}

TEST_CASE("templates are parsed once and reused") {
  auto env = makeEnv({{"t", "{{ n }}"}});
  for (int i = 0; i < 3; ++i) {
    Value ctx = Value::newDict();
    ctx.dict().setString("n", Value::integer(i));
    CHECK(env->render("t", ctx) == std::to_string(i));
  }
}

TEST_CASE("the render context must be a dict") {
  auto env = makeEnv({{"t", "x"}});
  CHECK_THROWS_WITH(env->render("t", Value::newList()),
                    "t: the render context must be a dict, not `list`");
  CHECK(env->render("t", Value()) == "x");
}

TEST_CASE("strings with invalid UTF-8 pass through unchanged") {
  auto env = makeEnv({{"t", "{{ s }}|{{ s | upper }}|{{ s | length }}"}});
  Value ctx = Value::newDict();
  ctx.dict().setString("s", Value::string("a\xff\xfe"));
  CHECK(env->render("t", ctx) == "a\xff\xfe|A\xff\xfe|3");
}

TEST_CASE("undefined hints explain themselves when used") {
  CHECK(renderError("{{ [] | first | upper }}x{{ ([] | first).x }}") ==
        "t:1:42: no first item, sequence was empty");
  CHECK(renderError("{% from 't2' import nope %}{{ nope() }}") ==
        "t:1:4: template `t2` not found; looked in no template directories");
}
