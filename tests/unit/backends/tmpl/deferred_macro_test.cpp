// Deferred macro bodies (backends/tmpl/parser/deferred_macro.cpp): a built-in template's
// top-level macros are parsed on their first call. Each case compiles the same library once
// as a built-in (deferred) and once in memory (parsed at once) and compares what they show.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "backends/tmpl/environment.h"
#include "tmpl_test_util.h"

namespace smachac::tmpl {
namespace {

using testing::context;

struct Library {
  std::string text;
  std::vector<EmbeddedFile> table;

  explicit Library(std::string source) : text(std::move(source)) {
    table.push_back({"lib/L.tpl.py", text});
    table.push_back({"lib/Inc.tpl.py", "{% block from_include %}{% endblock %}"});
  }

  /// An environment that finds L.tpl.py built in (deferred) or in memory (at once).
  std::unique_ptr<Environment> env(bool builtin, const std::string& main) const {
    auto out = std::make_unique<Environment>(std::vector<std::string>{},
                                             std::vector<std::string>{"lib/"}, table);
    if (!builtin) out->addTemplate("L.tpl.py", text);
    out->addTemplate("main", main);
    return out;
  }

  std::string render(bool builtin, const std::string& main, const std::string& yaml = "{}") const {
    try {
      return env(builtin, main)->render("main", context(yaml));
    } catch (const TemplateError& e) {
      std::string what = e.what();
      return "error " + what.substr(what.find(':'));  // without the origin, which differs
    }
  }
};

const char* const kLibrary = R"({% macro shout(word, times=2) -%}
{{ (word | upper) ~ suffix * times }}{% for c in word %}{{ loop.index }}{% endfor %}
{%- endmacro %}
{% macro wrap() %}[{{ caller() }}]{% endmacro %}
{% macro outer(x) %}{% macro inner(y) %}<{{ y }}>{% endmacro %}{{ inner(x) }}{% endmacro %}
{% macro extra() %}{{ varargs | length }} {{ kwargs | dictsort }}{% endmacro %}
{% macro checked(v) %}{% if v is defined and v is not none %}{{ v }}{% else %}-{% endif %}{% endmacro %}
{% macro filtered() %}{% filter title %}a title{% endfilter %}{% set t = 3 %}{{ t }}{% endmacro %}
{% set suffix = '!' %})";

const char* const kMain = R"({% import 'L.tpl.py' as L %}{{ L.shout('hi') }} {{ L.shout('a', 1) }}
{% call L.wrap() %}inside{% endcall %} {{ L.outer(5) }} {{ L.extra(1, 2, k=3) }}
{{ L.checked(none) }}{{ L.checked(4) }}{{ L.checked(missing) }} {{ L.filtered() }})";

TEST_CASE("deferred macro bodies render as bodies parsed at once") {
  Library library(kLibrary);
  std::string expected = library.render(false, kMain);
  CHECK(expected.find("error") == std::string::npos);
  CHECK(library.render(true, kMain) == expected);
  // Called twice and through `from ... import`: the body is parsed once and reused.
  std::string twice = "{% from 'L.tpl.py' import shout %}{{ shout('x') }}{{ shout('y') }}";
  CHECK(library.render(true, twice) == library.render(false, twice));
}

TEST_CASE("a macro body with a block or a template reference is parsed at once") {
  Library library(
      "{% macro m() %}{% include 'Inc.tpl.py' %}{% endmacro %}"
      "{% macro n() %}{% block in_macro %}{% endblock %}{% endmacro %}");
  CHECK(library.env(true, "")->listBlocks("L.tpl.py") ==
        std::vector<std::string>{"from_include", "in_macro"});
  CHECK(library.env(false, "")->listBlocks("L.tpl.py") ==
        std::vector<std::string>{"from_include", "in_macro"});
}

TEST_CASE("an unknown filter or test in a built-in macro body is reported when it loads") {
  for (const char* text :
       {"{% macro m() %}{{ 1 | no_such_filter }}{% endmacro %}",
        "{% macro m() %}{{ 1 is no_such_test }}{% endmacro %}",
        "{% macro m() %}{% filter no_such_filter %}{% endfilter %}{% endmacro %}"}) {
    CAPTURE(text);
    Library library(text);
    std::string main = "{% import 'L.tpl.py' as L %}loaded";
    std::string eager = library.render(false, main);
    CHECK(eager.starts_with("error :1:"));
    CHECK(library.render(true, main) == eager);
  }
}

TEST_CASE("a syntax error in a deferred body is reported at the first call, at its place") {
  Library library("{% macro ok() %}ok{% endmacro %}\n{% macro bad() %}{{ 1 + }}{% endmacro %}");
  std::string call_bad = "{% import 'L.tpl.py' as L %}{{ L.bad() }}";
  std::string eager = library.render(false, call_bad);
  CHECK(eager == "error :2:25: unexpected `}}`");
  CHECK(library.render(true, call_bad) == eager);
  // Built-in templates are known to compile (the build's tests compile each one at once),
  // so a macro that is never called is never parsed.
  CHECK(library.render(true, "{% import 'L.tpl.py' as L %}{{ L.ok() }}") == "ok");
}

}  // namespace
}  // namespace smachac::tmpl
