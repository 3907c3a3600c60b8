// SMACHA's templater operations: renderBlock, listBlocks, moduleVariables, metaBlock, skipped
// blocks, and template name resolution across directories and built-in sets.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "backends/tmpl/values/value_print.h"
#include "tests/unit/backends/tmpl/tmpl_test_util.h"

using smachac::EmbeddedFile;
using smachac::tmpl::Environment;
using smachac::tmpl::RenderOptions;
using smachac::tmpl::Value;
using smachac::tmpl::testing::context;
using smachac::tmpl::testing::makeEnv;

namespace {

const std::vector<std::pair<std::string, std::string>> kStateSet = {
    {"Child",
     "{% block meta %}\nname: Child\n{% endblock meta %}\n"
     "before extends\n"
     "{% extends 'Base' %}\n"
     "{% include 'Helper' %}\n"
     "{% block imports %}\n{{ super() }}\nimport child\n{% endblock imports %}\n"
     "{% block body %}\nchild body {{ shout(name) }}\n{% endblock body %}\n"},
    {"Base",
     "{% from 'Lib' import shout %}\n"
     "{% block imports %}import base{% endblock imports %}\n"
     "{% block body %}{% endblock body %}\n"
     "{% block footer %}# footer{% endblock footer %}\n"},
    {"Helper",
     "{% block imports %}import helper{% endblock imports %}\n"
     "{% block class_defs %}class Helper: pass{% endblock class_defs %}\n"},
    {"Lib",
     "{% block meta %}\nname: Lib\n{% endblock meta %}\n"
     "{% macro shout(x) %}{{ x | upper }}!{% endmacro %}\n"},
};

std::string block(Environment& env, const std::string& name) {
  return env.renderBlock("Child", name, context("name: joe"));
}

}  // namespace

TEST_CASE("renderBlock renders the whole template with every other block removed") {
  auto env = makeEnv(kStateSet);
  CHECK(block(*env, "imports") == "before extends\nimport helper\n\n\nimport base\nimport child\n");
  CHECK(block(*env, "body") == "before extends\n\n\n\n\nchild body JOE!\n");
  CHECK(block(*env, "class_defs") == "before extends\n\nclass Helper: pass\n");
  CHECK(block(*env, "footer") == "before extends\n\n\n\n\n# footer\n");
  CHECK(block(*env, "meta") == "name: Child\n\nbefore extends\n");
  CHECK(block(*env, "absent") == "before extends\n");
}

TEST_CASE("an imported module is made under each render's skipped blocks, in any order") {
  // Lib names no template, so renders that skip its blocks alike share its module; these two
  // skip its `imports` block differently and must not.
  const std::vector<std::pair<std::string, std::string>> set = {
      {"Lib", "{% block imports %}LIB{% endblock %}{% macro f() %}f{% endmacro %}"},
      {"T",
       "{% import 'Lib' as lib %}{% block imports %}[{{ lib }}{{ lib.f() }}]{% endblock %}"
       "{% block body %}({{ lib }}{{ lib.f() }}){% endblock %}"}};
  auto body_first = makeEnv(set);
  CHECK(body_first->renderBlock("T", "body", Value::newDict()) == "(f)\n");
  CHECK(body_first->renderBlock("T", "imports", Value::newDict()) == "[LIBf]\n");
  CHECK(body_first->renderBlock("T", "body", Value::newDict()) == "(f)\n");
  auto imports_first = makeEnv(set);
  CHECK(imports_first->renderBlock("T", "imports", Value::newDict()) == "[LIBf]\n");
  CHECK(imports_first->renderBlock("T", "body", Value::newDict()) == "(f)\n");
}

TEST_CASE("renderBlock strips with Python's whitespace set and appends a newline") {
  auto env = makeEnv({{"t", "\u3000 {% block b %}\n  x  \n{% endblock %}\x0c\n"},
                      {"e", "{% block b %} \n {% endblock %}"}});
  CHECK(env->renderBlock("t", "b", Value::newDict()) == "x\n");
  CHECK(env->renderBlock("e", "b", Value::newDict()) == "");
}

TEST_CASE("listBlocks follows extends, include and imports") {
  auto env = makeEnv(kStateSet);
  CHECK(env->listBlocks("Child") ==
        std::vector<std::string>{"body", "class_defs", "footer", "imports", "meta"});
  CHECK(env->listBlocks("Lib") == std::vector<std::string>{"meta"});
}

TEST_CASE("render skips the requested blocks everywhere") {
  auto env = makeEnv(kStateSet);
  RenderOptions options{{"meta", "footer", "class_defs"}};
  CHECK(env->render("Child", context("name: x"), options) ==
        "\nbefore extends\nimport helper\n\n\nimport base\nimport child\n\n\nchild body X!\n\n");
}

TEST_CASE("moduleVariables exports top-level sets and macros, also the parent's") {
  auto env =
      makeEnv({{"Child",
                "{% extends 'Base' %}{% set sm_name = 'sm_' ~ name %}"
                "{% if not recorder is defined %}{% set recorder = 'rec' %}{% endif %}"
                "{% from 'Lib' import shout %}{% set _hidden = 1 %}"
                "{% macro m() %}{% endmacro %}{% block b %}{% set inner = 1 %}{% endblock %}"},
               {"Base", "{% set defined_headers = [] %}{% block b %}{% endblock %}"},
               {"Lib", "{% macro shout() %}{% endmacro %}"}});
  std::vector<std::string> lines;
  for (const auto& [name, value] : env->moduleVariables("Child", context("name: top"))) {
    lines.push_back(name + "=" + smachac::tmpl::repr(value));
  }
  CHECK(lines == std::vector<std::string>{"defined_headers=[]", "m=<Macro 'm'>", "recorder='rec'",
                                          "sm_name='sm_top'"});
}

TEST_CASE("moduleVariables runs blocks; macros it exports stay callable") {
  auto env = makeEnv({{"t",
                       "{% macro hello(n) %}hi {{ n }}{% endmacro %}{% block b %}{% do "
                       "seen.append(1) %}{% endblock %}"},
                      {"use", "{{ hello('there') }}"}});
  Value ctx = context("seen: []");
  auto vars = env->moduleVariables("t", ctx);
  REQUIRE(vars.size() == 1);
  CHECK(smachac::tmpl::str(*ctx.dict().findString("seen")) == "[1]");
  Value use_ctx = Value::newDict();
  use_ctx.dict().setString("hello", vars[0].second);
  CHECK(env->render("use", use_ctx) == "hi there");
}

TEST_CASE("metaBlock renders the template's own meta block with an empty context") {
  auto env = makeEnv(kStateSet);
  CHECK(env->metaBlock("Child") == "\nname: Child\n");
  CHECK(env->metaBlock("Base") == std::nullopt);
  auto rendered = makeEnv({{"t", "{% block meta %}a: {{ 1 + 1 }}{{ x }}{% endblock %}"}});
  CHECK(rendered->metaBlock("t") == "a: 2");
}

TEST_CASE("the defined_headers list de-duplicates across block renders") {
  auto env = makeEnv({{"S",
                       "{% block imports %}{% if 'import_x' not in defined_headers %}import x"
                       "{% do defined_headers.append('import_x') %}{% endif %}{% endblock %}"
                       "{% block body %}body{% endblock %}"}});
  Value ctx = context("defined_headers: []");
  CHECK(env->renderBlock("S", "imports", ctx) == "import x\n");
  CHECK(env->renderBlock("S", "body", ctx) == "body\n");
  CHECK(env->renderBlock("S", "imports", ctx) == "");
}

namespace {

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("smachac_tmpl_" + name)) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  void write(const std::string& name, const std::string& text) const {
    std::filesystem::create_directories((path / name).parent_path());
    std::ofstream(path / name) << text;
  }
};

}  // namespace

TEST_CASE("template names resolve through directories in order, then built-in sets") {
  TempDir first("first"), second("second");
  first.write("Zed.tpl", "first Zed.tpl");
  second.write("Zed.tpl.py", "second Zed.tpl.py");
  second.write("Only.tpl.cfg", "second Only.tpl.cfg");
  second.write("Only.tpl.abc", "second Only.tpl.abc");
  second.write("sub/Nested.tpl.py", "nested");
  first.write("State.tpl.py", "user override of State");
  first.write("Literal", "a file literally named Literal");
  static const EmbeddedFile kBuiltins[] = {
      {"smach/State.tpl.py", "built-in State"},
      {"smach/Base.tpl.py", "built-in Base"},
      {"smach_ros/Base.tpl.py", "ros Base"},
      {"smach_ros/Ros.tpl", "ros only"},
  };
  Environment env({first.path.string(), second.path.string()}, {"smach", "smach_ros/"}, kBuiltins);
  CHECK(env.resolveScriptTemplate("Zed") == "Zed.tpl");
  CHECK(env.resolveScriptTemplate("Only") == "Only.tpl.abc");
  CHECK(env.resolveScriptTemplate("sub/Nested") == "sub/Nested.tpl.py");
  CHECK(env.resolveScriptTemplate("State") == "State.tpl.py");
  CHECK(env.resolveScriptTemplate("Base") == "Base.tpl.py");
  CHECK(env.resolveScriptTemplate("Ros") == "Ros.tpl");
  CHECK(env.resolveScriptTemplate("Literal") == "Literal");
  CHECK(env.resolveScriptTemplate("Missing") == std::nullopt);
  CHECK(env.resolveScriptTemplate("../etc/passwd") == std::nullopt);
  Value ctx = Value::newDict();
  CHECK(env.render("State.tpl.py", ctx) == "user override of State");
  CHECK(env.render("Base.tpl.py", ctx) == "built-in Base");
  CHECK(env.render("Zed.tpl", ctx) == "first Zed.tpl");
  CHECK(env.render("Zed.tpl.py", ctx) == "second Zed.tpl.py");
  CHECK(env.render("./sub//Nested.tpl.py", ctx) == "nested");
  CHECK_FALSE(env.hasTemplate("../second/Zed.tpl.py"));
  CHECK(env.hasTemplate("Ros.tpl"));
}

TEST_CASE("names inside templates are exact file names searched in the same order") {
  TempDir dir("inner");
  dir.write("Child.tpl.py", "{% extends 'State.tpl.py' %}{% block b %}child{% endblock %}");
  static const EmbeddedFile kBuiltins[] = {{"smach/State.tpl.py", "[{% block b %}{% endblock %}]"}};
  Environment env({dir.path.string()}, {"smach/"}, kBuiltins);
  CHECK(env.render("Child.tpl.py", Value::newDict()) == "[child]");
  dir.write("Broken.tpl.py", "{% extends 'State' %}");
  CHECK_THROWS_WITH(env.render("Broken.tpl.py", Value::newDict()),
                    doctest::Contains("template `State` not found"));
}
