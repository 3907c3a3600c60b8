// The renderer's shortcuts give what the general paths give: export hints of
// `from ... import`, the context's name filter, one-line `indent`, one-character repetition
// and the 8-byte steps of renderBlock's strip and of the line-break scan.
#include <doctest/doctest.h>

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
  auto indented = [](const std::string& s) {
    Value ctx = Value::newDict();
    ctx.dict().setString("s", Value::string(s));
    auto env = makeEnv({{"t", "{{ s | indent(2) }}|{{ s | indent(2, true, true) }}"}});
    return env->render("t", ctx);
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
