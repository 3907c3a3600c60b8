// The renderer's shortcuts give what the general paths give: export hints of
// `from ... import`, the context's name filter, one-line `indent`, a printed `indent` written
// straight into the output, one-character repetition and the 8-byte steps of renderBlock's
// strip and of the line-break scan.
#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

#include "tests/unit/backends/tmpl/tmpl_test_util.h"

using smachac::tmpl::Value;
using smachac::tmpl::testing::context;
using smachac::tmpl::testing::makeEnv;
using smachac::tmpl::testing::render;

TEST_CASE("from-import finds names in modules that export them in another order") {
  auto env = makeEnv({{"t", "{% from name import a, b %}{{ a }}{{ b }}"},
                      {"m1", "{% set a = 1 %}{% set b = 2 %}"},
                      {"m2", "{% set b = 3 %}{% set a = 4 %}"},
                      {"m3", "{% set a = 5 %}"}});
  CHECK(env->render("t", context("name: m1")) == "12");
  CHECK(env->render("t", context("name: m2")) == "43");
  CHECK(env->render("t", context("name: m1")) == "12");
  CHECK(env->render("t", context("name: m3")) == "5");  // `b` undefined: prints nothing
}

TEST_CASE("many context variables resolve through the name filter") {
  std::string source;
  std::string expected;
  for (int i = 0; i < 100; ++i) {
    source += "{% set v" + std::to_string(i) + " = " + std::to_string(i) + " %}";
  }
  source += "{% include 'inc' %}";
  std::string inc;
  for (int i = 0; i < 100; i += 7) {
    inc += "{{ v" + std::to_string(i) + " }},";
    expected += std::to_string(i) + ",";
  }
  inc += "{{ w is defined }}";
  expected += "False";
  auto env = makeEnv({{"t", source}, {"inc", inc}});
  CHECK(env->render("t", Value::newDict()) == expected);
}

TEST_CASE("one-line indent and one-character repetition") {
  CHECK(render("{{ 'x' | indent(0, true) }}|{{ 'x' | indent(2, true) }}|{{ 'x' | indent(2) }}") ==
        "x|  x|x");
  CHECK(render("{{ 'a\\r\\nb' | indent(0) }}") == "a\nb");
  CHECK(render("{{ ' ' * 3 }}|{{ 'ab' * 2 }}|{{ '-' * 0 }}|{{ '-' * -1 }}") == "   |abab||");
}

TEST_CASE("renderBlock strips long runs of blank lines and Python's other whitespace") {
  auto env = makeEnv({{"t",
                       "{% block b %}\n\n\n\n\n\n\n\n\n\t        \n x y \n\n\n \n\n\n\n\n\n\n\n "
                       "\u3000{% endblock %}"},
                      {"u", "{% block b %}                \n{% endblock %}"}});
  CHECK(env->renderBlock("t", "b", Value::newDict()) == "x y\n");
  CHECK(env->renderBlock("u", "b", Value::newDict()).empty());
}

TEST_CASE("indent finds every kind of line break, in long plain runs and across 8-byte steps") {
  Value ctx = Value::newDict();
  ctx.dict().setString("s", Value::string("abcdefgh1234567\r\nabcdefghijklmnop\u2028xy\x1c"
                                          "abcdefghi\u0085j\r\r\nlast line here!"));
  auto env = makeEnv({{"t", "{{ s | indent(2) }}"}});
  CHECK(env->render("t", ctx) ==
        "abcdefgh1234567\n  abcdefghijklmnop\n  xy\n  abcdefghi\n  j\n\n  last line here!");
}

TEST_CASE("indent of a text that ends with a line break adds Jinja2's empty last line") {
  // Printed (written into the output) and as values: the same text.
  auto indented = [](const std::string& s) {
    Value ctx = Value::newDict();
    ctx.dict().setString("s", Value::string(s));
    auto env = makeEnv({{"printed", "{{ s | indent(2) }}|{{ s | indent(2, true, true) }}"},
                        {"values",
                         "{% set a = s | indent(2) %}{% set b = s | indent(2, true, "
                         "true) %}{{ a ~ '|' ~ b }}"}});
    std::string printed = env->render("printed", ctx);
    CHECK(env->render("values", ctx) == printed);
    return printed;
  };
  // Expected texts from python3-jinja2 3.1.
  CHECK(indented("a\r") == "a|  a");  // "\r" and the added "\n" are one break
  CHECK(indented("a\r\n") == "a\n|  a\n  ");
  CHECK(indented("a\n") == "a\n|  a\n  ");
  CHECK(indented("a\u0085") == "a\n|  a\n  ");
  CHECK(indented("a\u2028") == "a\n|  a\n  ");
  CHECK(indented("\r") == "|  ");
  CHECK(indented("\n\n") == "\n\n|  \n  \n  ");
  CHECK(indented("a\n\rb\r") == "a\n\n  b|  a\n  \n  b");
}

TEST_CASE("a printed indent keeps the limits, steps and errors of the indented string") {
  // Each template printed as written (indent writes into the output) and with `~ ''` after
  // the filter (the indented string is made, then printed): the same error, at the filter's
  // name for the filter's errors and at the `{{` for the output's.
  std::vector<std::pair<std::string, std::string>> cases = {
      {"{{ 'ab\\nab\\nab' | indent(5)", "t:1:19: string too large (limit 16)"},
      {"{% for i in range(4) %}{{ 'ab\\nc' | indent(1)",
       "t:1:24: output too large (limit 16 bytes)"},
      {"{{ 7 | indent(1)", "t:1:8: `indent` expects a string, not `int`"},
      {"{{ 'a\\nb' | indent('x', wide=1)",
       "t:1:13: `indent` got an unexpected keyword argument `wide`"}};
  Value ctx = Value::newDict();
  for (const auto& [source, error] : cases) {
    std::string end = source.find("{% for") == 0 ? " }}{% endfor %}" : " }}";
    auto env = makeEnv({{"t", source + end}});
    env->setLimits({.steps = 1000, .string_bytes = 16, .items = 6});
    CHECK_THROWS_WITH(env->render("t", ctx), error.c_str());
    auto kept = makeEnv({{"t", source + " ~ ''" + end}});
    kept->setLimits({.steps = 1000, .string_bytes = 16, .items = 6});
    CHECK_THROWS_WITH(kept->render("t", ctx), error.c_str());
  }
  // 50 steps for s, 75 for its indented text: past 100 whether it is printed or kept.
  for (std::string after : {"", " ~ ''"}) {
    auto env = makeEnv({{"t", "{% set s = 'x\\n' * 6400 %}{{ s | indent(1)" + after + " }}"}});
    env->setLimits({.steps = 100});
    CHECK_THROWS_WITH(env->render("t", ctx), "t:1:34: template execution exceeded 100 steps");
    env->setLimits({.steps = 200});
    CHECK(env->render("t", ctx).size() == 19199);
  }
}
