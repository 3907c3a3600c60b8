// The library header and the `cpp_library` global.
#include "backends/cpp/cpp_library.h"

#include "backends/generator/state_variables.h"
#include "backends/tmpl/error.h"

namespace smachac::backends::cpp {
namespace {

constexpr const char* kHeaderTemplate = "LibraryHeader.tpl.h";

tmpl::Value str(const std::string& text) { return tmpl::Value::string(text); }

}  // namespace

tmpl::Value libraryGlobal(const std::optional<LibraryNames>& library) {
  if (!library) return tmpl::Value::boolean(false);
  tmpl::Value global = tmpl::Value::newDict();
  global.dict().setString("namespace", str(library->name_space));
  global.dict().setString("header", str(library->header));
  global.dict().setString("function", str(kLibraryFunction));
  return global;
}

std::optional<std::string> renderLibraryHeader(const ir::Module& module, tmpl::Environment& env,
                                               generator::ValueConverter& converter,
                                               const generator::TemplatePath& path,
                                               EmitContext& context) {
  const ir::State& root = module.state(module.root());
  tmpl::Value vars = tmpl::Value::newDict();
  vars.dict().setString("name", str(root.name.text));
  generator::addStateKeys(root, vars, converter);
  try {
    std::string text = env.render(kHeaderTemplate, vars, {.skip_blocks = {"meta"}});
    size_t end = text.find_last_not_of(" \t\r\n");
    size_t begin = text.find_first_not_of(" \t\r\n");
    if (end == std::string::npos) return std::string();
    return text.substr(begin, end - begin + 1) + "\n";
  } catch (const tmpl::TemplateError& e) {
    generator::TemplateFiles files(context.sources, path.builtins);
    context.diags.emit<DiagKind::TemplateError>(files.locate(e), ForeignMessage(e.message()));
    return std::nullopt;
  }
}

}  // namespace smachac::backends::cpp
