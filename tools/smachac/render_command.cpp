// `smachac render`: renders one template (by name or path) with a JSON or YAML context, or one
// of its blocks in isolation with --block, through the template engine (backends/tmpl), with
// the SMACH target's template extensions (pyrepr, forced_string) registered.
//   smachac render TEMPLATE [--context ctx.json|ctx.yml] [-I dir]... [--builtin-set smach]...
//                  [--block NAME] [--skip-block NAME]... [-o out]
// Template errors print as `file:line:col: error: message [template-error]` and context file
// errors as `[context-error]` (exit 1); usage and I/O errors exit 2.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <optional>

#include "backends/generator/template_values.h"
#include "backends/smach/python_extensions.h"
#include "backends/tmpl/environment.h"
#include "backends/tmpl/values/value_convert.h"
#include "ir/support/file_text.h"
#include "templates/builtin_templates.h"
#include "tools/smachac/commands.h"
#include "tools/smachac/output.h"
#include "tools/smachac/session.h"

namespace smachac::driver {
namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  std::string template_arg;
  std::string context_path;
  std::vector<std::string> template_dirs;
  std::vector<std::string> builtin_sets;
  std::vector<std::string> skip_blocks;
  std::string block;
  std::string output = "-";
};

int reportError(const tmpl::TemplateError& e, const char* kind) {
  std::cerr << e.file();
  if (e.line() > 0) std::cerr << ":" << e.line() << ":" << e.column();
  std::cerr << ": error: " << e.message() << " [" << kind << "]\n";
  return kExitInputError;
}

std::optional<int> parse(RenderOptions& o, const Args& args) {
  CLI::App app{"smachac render: render a template with a JSON or YAML context", "smachac render"};
  app.add_option("template", o.template_arg, "template name (Foo, Foo.tpl.py) or file path")
      ->required()
      ->type_name("TEMPLATE");
  app.add_option("--context", o.context_path, "render variables (.json, .yml or .yaml)")
      ->type_name("FILE");
  app.add_option("-I", o.template_dirs, "template search directory (repeatable, searched first)")
      ->type_name("DIR");
  app.add_option("--builtin-set", o.builtin_sets, "built-in template set (default: smach)")
      ->type_name("SET");
  app.add_option("--block", o.block, "render only this block, isolated and stripped")
      ->type_name("NAME");
  app.add_option("--skip-block", o.skip_blocks, "remove this block while rendering (repeatable)")
      ->type_name("NAME");
  app.add_option("-o", o.output, "output file (default: stdout)")->type_name("FILE");
  return parseArgs(app, args);
}

tmpl::Value loadContext(const std::string& path, const std::string& text) {
  std::string ext = fs::path(path).extension().string();
  size_t first = text.find_first_not_of(" \t\r\n");
  bool json = ext == ".json" ||
              (ext != ".yml" && ext != ".yaml" && first != std::string::npos && text[first] == '{');
  tmpl::Value ctx = json ? tmpl::parseJson(text, path) : tmpl::parseYaml(text, path);
  if (ctx.isNone()) return tmpl::Value::newDict();
  if (!ctx.isDict()) throw tmpl::TemplateError(path, 0, 0, "the context must be a mapping");
  return ctx;
}

int render(RenderOptions& o) {
  tmpl::Value context = tmpl::Value::newDict();
  if (!o.context_path.empty()) {
    std::optional<std::string> text = readFileText(o.context_path);
    if (!text) return usageError("cannot read `" + o.context_path + "`");
    try {
      context = loadContext(o.context_path, *text);
    } catch (const tmpl::TemplateError& e) {
      return reportError(e, "context-error");
    }
  }
  std::string name = o.template_arg;
  std::error_code ec;
  if (fs::is_regular_file(o.template_arg, ec)) {
    fs::path path(o.template_arg);
    o.template_dirs.insert(o.template_dirs.begin(),
                           path.has_parent_path() ? path.parent_path().string() : ".");
    name = path.filename().string();
  }
  if (o.builtin_sets.empty()) o.builtin_sets.push_back("smach");
  tmpl::Environment env(o.template_dirs, o.builtin_sets, templates::builtinTemplates());
  generator::ValueConverter converter;  // the SMACH templates' filters and tests (pyrepr, ...)
  backends::smach::registerPythonExtensions(env, converter, /*include_comments=*/false);
  if (std::optional<std::string> resolved = env.resolveScriptTemplate(name)) name = *resolved;
  tmpl::RenderOptions options{o.skip_blocks};
  std::string out = o.block.empty() ? env.render(name, context, options)
                                    : env.renderBlock(name, o.block, context, options);
  if (std::optional<std::string> error = writeFileAtomically(o.output, out)) {
    return usageError("cannot write `" + o.output + "`: " + *error);
  }
  return kExitOk;
}

}  // namespace

int runRender(const Args& args) {
  RenderOptions o;
  if (std::optional<int> code = parse(o, args)) return *code;
  try {
    return render(o);
  } catch (const tmpl::TemplateError& e) {
    return reportError(e, "template-error");
  }
}

}  // namespace smachac::driver
