// The build's precompiled meta table against the run-time parse of every built-in template,
// and the lookup's choice between them (an -I directory's template comes first).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "backends/cpp/cpp_extensions.h"
#include "backends/meta/template_meta.h"
#include "backends/meta/template_meta_lookup.h"
#include "backends/smach/python_extensions.h"
#include "templates/builtin_meta.h"
#include "templates/builtin_templates.h"

namespace {

using smachac::backends::TemplateMeta;
using smachac::backends::TemplateVariable;
namespace fs = std::filesystem;
namespace templates = smachac::templates;

/// What a compile read before the table: the meta block through the engine, then the parser.
std::optional<TemplateMeta> parsedAtRunTime(std::string_view path) {
  size_t slash = path.find('/');
  std::string set(path.substr(0, slash + 1));
  smachac::tmpl::Environment env({}, {set}, templates::builtinTemplates());
  smachac::generator::ValueConverter converter;
  if (set == "cpp/") {
    smachac::backends::cpp::registerCppExtensions(env, converter, false);
  } else {
    smachac::backends::smach::registerPythonExtensions(env, converter, false);
  }
  std::optional<std::string> text = env.metaBlock(path.substr(slash + 1));
  return text ? smachac::backends::parseTemplateMeta(*text) : std::nullopt;
}

std::vector<std::string> rowStrings(std::span<const std::string_view> items) {
  return {items.begin(), items.end()};
}

void checkSame(const templates::BuiltinMeta& row, const std::optional<TemplateMeta>& parsed) {
  REQUIRE(row.parsed == parsed.has_value());
  if (!parsed) return;
  CHECK(rowStrings(row.outcomes) == parsed->outcomes);
  REQUIRE(row.variables.size() == parsed->variables.size());
  for (size_t i = 0; i < row.variables.size(); ++i) {
    const TemplateVariable& expected = parsed->variables[i];
    CHECK(row.variables[i].name == expected.name);
    CHECK(rowStrings(row.variables[i].types) == expected.types);
    CHECK(row.variables[i].required == expected.required);
    CHECK(row.variables[i].alternative_group == expected.alternative_group);
  }
}

bool sameMeta(const std::optional<TemplateMeta>& a, const std::optional<TemplateMeta>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  if (a->outcomes != b->outcomes || a->variables.size() != b->variables.size()) return false;
  for (size_t i = 0; i < a->variables.size(); ++i) {
    const TemplateVariable& x = a->variables[i];
    const TemplateVariable& y = b->variables[i];
    if (x.name != y.name || x.types != y.types || x.required != y.required ||
        x.alternative_group != y.alternative_group) {
      return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("every code target's template has a precompiled row equal to the run-time parse") {
  // A meta block with template syntax in it gets no row (it is read at run time): keep the
  // built-in ones plain text so that none is parsed during a compile. dot/ renders with its
  // own filters and is never checked against meta blocks: it has no row.
  size_t checked = 0;
  size_t with_meta = 0;
  for (const smachac::EmbeddedFile& file : templates::builtinTemplates()) {
    CAPTURE(file.path);
    const templates::BuiltinMeta* row = templates::findBuiltinMeta(file.path);
    if (file.path.starts_with("dot/")) continue;
    REQUIRE(row != nullptr);
    CHECK(row->path == file.path);
    checkSame(*row, parsedAtRunTime(file.path));
    ++checked;
    if (row->parsed) ++with_meta;
  }
  CHECK(templates::builtinMetas().size() == checked);
  CHECK(with_meta > 50);  // the code targets' templates document their variables
  CHECK(templates::findBuiltinMeta("smach/NoSuchTemplate.tpl.py") == nullptr);
}

TEST_CASE("the lookup takes the table for built-in templates, the parse for others") {
  smachac::generator::TemplatePath path{{}, {"smach/"}, templates::builtinTemplates()};
  smachac::tmpl::Environment env(path.dirs, path.builtin_sets, path.builtins);
  std::optional<TemplateMeta> base =
      smachac::backends::lookUpTemplateMeta(env, path, "Base.tpl.py");
  REQUIRE(base);
  CHECK(sameMeta(base, parsedAtRunTime("smach/Base.tpl.py")));
  CHECK(smachac::generator::builtinTemplatePath(path, "./Base.tpl.py") == "smach/Base.tpl.py");

  fs::path dir = fs::temp_directory_path() / "smachac_meta_lookup_test";
  fs::create_directories(dir);
  std::ofstream(dir / "Base.tpl.py") << "{% block meta %}\nvariables:\n- mine:\n    type: str\n"
                                        "outcomes: [own]\n{% endblock meta %}\n";
  path.dirs = {dir.string()};
  smachac::tmpl::Environment user_env(path.dirs, path.builtin_sets, path.builtins);
  CHECK_FALSE(smachac::generator::builtinTemplatePath(path, "Base.tpl.py"));
  std::optional<TemplateMeta> own =
      smachac::backends::lookUpTemplateMeta(user_env, path, "Base.tpl.py");
  fs::remove_all(dir);
  REQUIRE(own);
  REQUIRE(own->variables.size() == 1);
  CHECK(own->variables[0].name == "mine");
  CHECK(own->outcomes == std::vector<std::string>{"own"});
  CHECK_FALSE(smachac::generator::builtinTemplatePath(path, "Missing.tpl.py"));
}
