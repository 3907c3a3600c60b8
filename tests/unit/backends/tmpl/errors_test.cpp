// Every kind of template error, with its exact message and location.
#include <doctest/doctest.h>

#include "tests/unit/backends/tmpl/tmpl_test_util.h"

using smachac::tmpl::testing::renderError;

TEST_CASE("syntax errors name the construct, line and column") {
  CHECK(renderError("{% if x %}\nno end") ==
        "t:2:7: unexpected end of template; expected `elif`, `else` or `endif` to close `if` "
        "from line 1");
  CHECK(renderError("a\n  {% frobnicate %}") == "t:2:6: unknown tag `frobnicate`");
  CHECK(renderError("{% for x in y %}{% endfro %}") ==
        "t:1:20: unknown tag `endfro`; did you mean `endfor`?");
  CHECK(renderError("{% for x in y %}{% endif %}") ==
        "t:1:20: unknown tag `endif`; expected `endfor` or `else`");
  CHECK(renderError("{% if a %}{% for x in y %}{% endif %}") ==
        "t:1:30: unexpected `endif`; expected `endfor` or `else` first");
  CHECK(renderError("{{ 1 + }}") == "t:1:8: unexpected `}}`");
  CHECK(renderError("{{ (1 + 2 }}") == "t:1:11: unexpected `}`, expected `)`");
  CHECK(renderError("{{ a ! b }}") == "t:1:6: unexpected char `!`");
  CHECK(renderError("{% block a %}{% endblock b %}") == "t:1:26: expected `%}`, got `b`");
  CHECK(renderError("{% block a %}{% endblock %}{% block a %}{% endblock %}") ==
        "t:1:37: block `a` defined twice");
  CHECK(renderError("x {# open") == "t:1:3: missing end of comment tag");
  CHECK(renderError("{% raw %}x") == "t:1:1: missing end of raw directive");
  CHECK(renderError("{% for x in [1] %}{% extends 'b' %}{% endfor %}") ==
        "t:1:22: `extends` can only be used at the top level");
  CHECK(renderError("{% macro m(a=1, b) %}{% endmacro %}") ==
        "t:1:17: non-default argument follows default argument");
  CHECK(renderError("{{ 99999999999999999999 }}") == "t:1:4: integer literal is too large");
  CHECK(renderError("{{ '\\x4' }}") == "t:1:4: truncated \\x escape in string");
  CHECK(renderError("{% for loop in [1] %}{% endfor %}") ==
        "t:1:8: cannot assign to the special `loop` variable");
  CHECK(renderError("{% from 'x' import _p %}") ==
        "t:1:20: names starting with an underscore cannot be imported");
  CHECK(renderError("{{ x is defined is defined }}") ==
        "t:1:17: you cannot chain multiple tests with `is`");
}

TEST_CASE("unknown filters and tests are syntax errors with a suggestion") {
  CHECK(renderError("{{ x | uper }}") == "t:1:8: unknown filter `uper`; did you mean `upper`?");
  CHECK(renderError("{{ x | zzzzzz }}") == "t:1:8: unknown filter `zzzzzz`");
  CHECK(renderError("{% if x is defind %}{% endif %}") ==
        "t:1:12: unknown test `defind`; did you mean `defined`?");
  CHECK(renderError("{% if false %}{{ x | uppr }}{% endif %}") ==
        "t:1:22: unknown filter `uppr`; did you mean `upper`?");
}

TEST_CASE("undefined values fail when used") {
  CHECK(renderError("{{ missing.attr }}") == "t:1:12: `missing` is undefined");
  CHECK(renderError("{{ render_things(1) }}") == "t:1:4: `render_things` is undefined");
  CHECK(renderError("{% do headers.append(1) %}") == "t:1:15: `headers` is undefined");
  CHECK(renderError("{{ missing + 1 }}") == "t:1:12: `missing` is undefined");
  CHECK(renderError("{{ missing < 1 }}") == "t:1:12: `missing` is undefined");
  CHECK(renderError("{{ missing | indent(4) }}") == "t:1:14: `missing` is undefined");
  CHECK(renderError("{{ d.a.b }}", "d: {}") == "t:1:8: `dict` object has no attribute `a`");
  CHECK(renderError("{{ [1][5].x }}") == "t:1:11: `list` object has no element 5");
  CHECK(renderError("{% macro m(a) %}{{ a.b }}{% endmacro %}{{ m() }}") ==
        "t:1:22: parameter `a` was not provided");
}

TEST_CASE("type and arithmetic errors") {
  CHECK(renderError("{{ 1 / 0 }}") == "t:1:6: division by zero");
  CHECK(renderError("{{ 1 // 0 }}") == "t:1:6: division by zero");
  CHECK(renderError("{{ 5 % 0 }}") == "t:1:6: modulo by zero");
  CHECK(renderError("{{ 'a' + 1 }}") ==
        "t:1:8: unsupported operand types for `+`: `str` and `int`");
  CHECK(renderError("{{ 'a' < 1 }}") ==
        "t:1:8: `<` is not supported between instances of `str` and `int`");
  CHECK(renderError("{{ 9223372036854775807 + 1 }}") == "t:1:24: integer overflow");
  CHECK(renderError("{% for x in 5 %}{% endfor %}") == "t:1:4: `int` object is not iterable");
  CHECK(renderError("{{ x() }}", "x: 1") == "t:1:4: `int` object is not callable");
  CHECK(renderError("{{ [1] | join(1, 2, 3) }}") ==
        "t:1:10: `join` takes at most 2 argument(s) (3 given)");
  CHECK(renderError("{{ 'x' | indent(width='a', bogus=1) }}") ==
        "t:1:10: `indent` got an unexpected keyword argument `bogus`");
  CHECK(renderError("{{ 5 is expression }}") == "t:1:9: `expression` expects a string, not `int`");
  CHECK(renderError("{{ none | exptostr }}") ==
        "t:1:11: `exptostr` expects a string, not `NoneType`");
  CHECK(renderError("{% set a, b = [1, 2, 3] %}") ==
        "t:1:4: too many values to unpack (expected 2)");
  CHECK(renderError("{{ {[1]: 2} }}") == "t:1:4: unhashable type: `list`");
  CHECK(renderError("{{ 'x' * 1000000000 }}") == "t:1:8: string too large (limit 268435456)");
}

TEST_CASE("macro call errors point at the call") {
  CHECK(renderError("{% macro m(a) %}{% endmacro %}\n{{ m(1, 2) }}") ==
        "t:2:4: macro `m` takes not more than 1 argument(s)");
  CHECK(renderError("{% macro m(a) %}{% endmacro %}{{ m(b=2) }}") ==
        "t:1:34: macro `m` takes no keyword argument `b`");
}

TEST_CASE("errors inside other templates name that template") {
  auto env = smachac::tmpl::testing::makeEnv(
      {{"main", "{% include 'part' %}"}, {"part", "line\n{{ 1 / 0 }}"}});
  try {
    env->render("main", smachac::tmpl::Value::newDict());
    FAIL("expected an error");
  } catch (const smachac::tmpl::TemplateError& e) {
    CHECK(std::string(e.what()) == "part:2:6: division by zero");
    CHECK(e.file() == "part");
    CHECK(e.line() == 2);
    CHECK(e.column() == 6);
    CHECK(e.message() == "division by zero");
  }
  auto lib = smachac::tmpl::testing::makeEnv({{"main", "{% from 'lib' import m %}\n\n{{ m() }}"},
                                              {"lib", "{% macro m() %}{{ x.y }}{% endmacro %}"}});
  CHECK_THROWS_WITH(lib->render("main", smachac::tmpl::Value::newDict()),
                    "lib:1:21: `x` is undefined");
}

TEST_CASE("missing templates list where the engine looked") {
  CHECK(renderError("{% include 'nowhere' %}") ==
        "t:1:4: template `nowhere` not found; looked in no template directories");
  smachac::tmpl::Environment env({"/nonexistent/a", "/nonexistent/b"}, {"smach/"},
                                 smachac::tmpl::testing::kNoBuiltins);
  CHECK_THROWS_WITH(env.render("Foo.tpl.py", smachac::tmpl::Value::newDict()),
                    "Foo.tpl.py: template `Foo.tpl.py` not found; looked in `/nonexistent/a`, "
                    "`/nonexistent/b`, built-in `smach/`");
}

TEST_CASE("recursion and runaway templates are bounded") {
  CHECK(renderError("x{% include 't' %}") ==
        "t:1:5: maximum template recursion depth (200) exceeded");
  CHECK(renderError("{% extends 't' %}") ==
        "t:1:4: maximum template recursion depth (200) exceeded");
  CHECK(renderError("{% import 't' as m %}") ==
        "t:1:4: maximum template recursion depth (200) exceeded");
  CHECK(renderError("{% macro a() %}{{ a() }}{% endmacro %}{{ a() }}") ==
        "t:1:19: maximum template recursion depth (200) exceeded");
  CHECK(renderError(
            "{% for i in range(100000) %}{% for j in range(100000) %}{% endfor %}{% endfor %}") ==
        "t:1:32: template execution exceeded 50000000 steps");
  CHECK(renderError("{% set ns = namespace(s='x') %}{% for i in range(40) %}"
                    "{% set ns.s = ns.s ~ ns.s %}{% endfor %}") ==
        "t:1:75: string too large (limit 268435456)");
  CHECK(renderError("{% set l = [1] %}{% for i in range(40) %}{% do l.extend(l) %}{% endfor %}") ==
        "t:1:50: list too large (limit 4194304)");
}

TEST_CASE("an environment's limits replace the defaults, for its renders only") {
  auto env = smachac::tmpl::testing::makeEnv(
      {{"loop", "{% for i in range(5) %}{% for j in range(5) %}{% endfor %}{% endfor %}"},
       {"str", "{{ ('ab' * 8) | length }}|{{ 'ab' * 9 }}"},
       {"list", "{{ ([1, 2] * 3) | length }}|{{ [1, 2] * 4 }}"},
       {"out", "{% for i in range(5) %}abcd{% endfor %}"}});
  smachac::tmpl::Value ctx = smachac::tmpl::Value::newDict();
  env->setLimits({.steps = 20, .string_bytes = 16, .items = 6});
  CHECK_THROWS_WITH(env->render("loop", ctx), "loop:1:27: template execution exceeded 20 steps");
  CHECK_THROWS_WITH(env->render("str", ctx), "str:1:35: string too large (limit 16)");
  CHECK_THROWS_WITH(env->render("list", ctx), "list:1:39: list too large (limit 6)");
  CHECK_THROWS_WITH(env->render("out", ctx), "out:1:24: output too large (limit 16 bytes)");
  CHECK(smachac::tmpl::testing::render("{{ ('ab' * 9) | length }}") == "18");
  env->setLimits({});
  CHECK(env->render("str", ctx) == "16|ababababababababab");
}

TEST_CASE("the strings and lists a render creates count against its steps") {
  auto env = smachac::tmpl::testing::makeEnv(
      {{"strings",
        "{% set s = 'x' * 25600 %}{% for i in range(10) %}{% set t = s ~ i %}"
        "{% endfor %}"},
       {"lists", "{% for i in range(20) %}{% set l = [i] * 400 %}{% endfor %}"}});
  smachac::tmpl::Value ctx = smachac::tmpl::Value::newDict();
  env->setLimits({.steps = 300});
  // 100 steps for s, then 100 for each t and the loop's own: past 300 in the 2nd iteration.
  CHECK_THROWS_WITH(env->render("strings", ctx),
                    "strings:1:63: template execution exceeded 300 steps");
  // 25 steps per list (400 values of 16 bytes) and the loop's own: past 300 in the 12th.
  CHECK_THROWS_WITH(env->render("lists", ctx), "lists:1:40: template execution exceeded 300 steps");
  env->setLimits({.steps = 2000});
  CHECK(env->render("strings", ctx) == "");
  CHECK(env->render("lists", ctx) == "");
}

TEST_CASE("deeply nested input is rejected cleanly") {
  CHECK(renderError("{{ " + std::string(300, '(') + "1" + std::string(300, ')') + " }}") ==
        "t:1:37: template nested too deeply (limit 100)");
  std::string ifs;
  for (int i = 0; i < 300; ++i) ifs += "{% if true %}";
  CHECK(renderError(ifs).find("nested too deeply") != std::string::npos);
  std::string yaml = std::string(300, '[') + std::string(300, ']');
  CHECK_THROWS_WITH(smachac::tmpl::parseYaml(yaml, "deep.yml"),
                    doctest::Contains("nested too deeply"));
  CHECK_THROWS_WITH(smachac::tmpl::parseJson(yaml, "deep.json"),
                    doctest::Contains("nested too deeply"));
}

TEST_CASE("context files report their own location") {
  CHECK_THROWS_WITH(smachac::tmpl::parseJson("{\"a\": [1,\n", "c.json"),
                    doctest::Contains("c.json:2:1: invalid JSON: "));
  CHECK_THROWS_WITH(smachac::tmpl::parseYaml("a: [1, 2\nb: 3", "c.yml"),
                    doctest::Contains("c.yml:"));
  CHECK_THROWS_WITH(smachac::tmpl::parseYaml("a: 1\na: 2", "c.yml"), "c.yml: duplicate key a");
}
