// libFuzzer harness for the template engine: bytes → `main.tpl` (and, after a line
// `%%context`, a YAML render context) → every Environment operation. Fixed in-memory templates
// include, extend and import `main.tpl` and themselves, so mutual and self recursion are
// exercised. TemplateError is the expected outcome for bad input; any other exception, crash,
// hang, leak or sanitizer report is a bug (the engine's invariant: only TemplateError leaves it).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "backends/tmpl/environment.h"
#include "backends/tmpl/values/value_convert.h"
#include "templates/builtin_templates.h"

namespace {

using smachac::tmpl::Environment;
using smachac::tmpl::RenderOptions;
using smachac::tmpl::TemplateError;
using smachac::tmpl::Value;

constexpr std::string_view kContextMarker = "\n%%context\n";

/// Small bounds, so that runaway templates fail in milliseconds: the defaults (50M steps,
/// 256 MiB strings) are bounded too, but take seconds under the sanitizers.
constexpr smachac::tmpl::Limits kFuzzLimits{
    .steps = 20'000, .string_bytes = 64 << 10, .items = 4096};

/// Templates around the fuzzed one: each reaches `main.tpl` or itself in a different way.
constexpr std::pair<const char*, const char*> kFixedTemplates[] = {
    {"self.tpl", "[{% include 'self.tpl' %}]"},
    {"includer.tpl", "<{% include 'main.tpl' %}>"},
    {"child.tpl", "{% extends 'main.tpl' %}{% block a %}child {{ super() }}{% endblock %}"},
    {"importer.tpl", "{% import 'main.tpl' as m %}{{ m }}{% from 'main.tpl' import x %}{{ x }}"},
    {"base.tpl", "({% block a %}A{% endblock %}|{% block b %}{{ x }}{% endblock %})"},
    {"macros.tpl",
     "{% macro m(v, w=2) %}<{{ v }},{{ w }},{{ caller() if caller }}>"
     "{% endmacro %}{% set exported = [1, 'two', {'k': 3.5}] %}"},
};

struct FuzzInput {
  std::string main;
  Value context;
};

FuzzInput splitInput(std::string_view bytes) {
  FuzzInput input{std::string(bytes), Value::newDict()};
  size_t marker = bytes.find(kContextMarker);
  if (marker == std::string_view::npos) return input;
  input.main = std::string(bytes.substr(0, marker));
  try {
    Value parsed = smachac::tmpl::parseYaml(bytes.substr(marker + kContextMarker.size()), "ctx");
    if (parsed.isDict()) input.context = parsed;
  } catch (const TemplateError&) {
    // A context that does not parse leaves the empty one.
  }
  return input;
}

/// Runs one operation; TemplateError is a valid outcome.
template <typename Operation>
void attempt(Operation&& operation) {
  try {
    operation();
  } catch (const TemplateError& error) {
    (void)error.what();
  }
}

/// A custom filter, test and global, as the targets add them: the filter raises Fault (which
/// the engine must locate) for anything but a string.
void addExtensions(Environment& env) {
  env.addFilter("strict", [](const Value& input, const smachac::tmpl::CallArgs&) {
    if (!input.isString()) smachac::tmpl::fail("strict: expected a string");
    return input;
  });
  env.addTest("short", [](const Value& input, const smachac::tmpl::CallArgs&) {
    return input.isString() && input.s().size() < 4;
  });
  Value site = Value::newDict();
  site.dict().set(Value::string("name"), Value::string("fuzz"));
  env.addGlobal("site", site);
}

void exercise(Environment& env, const Value& context) {
  RenderOptions skip_meta{{"meta"}};
  attempt([&] { env.render("main.tpl", context); });
  attempt([&] { env.render("main.tpl", context, skip_meta); });
  attempt([&] {
    size_t rendered = 0;
    for (const std::string& block : env.listBlocks("main.tpl")) {
      if (++rendered > 3) break;
      env.renderBlock("main.tpl", block, context);
    }
  });
  attempt([&] { env.moduleVariables("main.tpl", context); });
  attempt([&] { env.metaBlock("main.tpl"); });
  for (const char* other : {"self.tpl", "includer.tpl", "child.tpl", "importer.tpl"}) {
    attempt([&] { env.render(other, context); });
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzInput input = splitInput({reinterpret_cast<const char*>(data), size});
  Environment env({}, {"smach/"}, smachac::templates::builtinTemplates());
  env.setLimits(kFuzzLimits);
  addExtensions(env);
  for (const auto& [name, source] : kFixedTemplates) env.addTemplate(name, source);
  env.addTemplate("main.tpl", std::move(input.main));
  exercise(env, input.context);
  return 0;
}
