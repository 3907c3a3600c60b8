// The C++ target: the Python-lambda check, environment, generator, output file(s).
#include "backends/cpp/cpp_target.h"

#include <memory>

#include "backends/cpp/cpp_extensions.h"
#include "backends/cpp/cpp_library.h"
#include "backends/generator/generator.h"
#include "templates/builtin_templates.h"

namespace smachac::backends::cpp {
namespace {

std::vector<std::string> skipBlocks(const EmitOptions& options) {
  std::vector<std::string> skip;
  if (!options.comments) skip.insert(skip.end(), {"upper_comments", "lower_comments"});
  if (!options.introspection) skip.insert(skip.end(), {"introspection_server", "spin"});
  return skip;
}

bool isPythonLambda(std::string_view code) {
  size_t start = code.find_first_not_of(" \t\r\n(");
  if (start == std::string_view::npos) return false;
  code.remove_prefix(start);
  if (!code.starts_with("lambda")) return false;
  return code.size() > 6 && (code[6] == ' ' || code[6] == ':' || code[6] == '\t');
}

class LambdaChecker {
 public:
  LambdaChecker(DiagnosticEmitter& diags, const std::string& state)
      : diags_(diags), state_(state) {}

  void check(const ir::Value& value, const std::string& what) {
    if (value.kind() == ir::ValueKind::Expression) {
      if (isPythonLambda(value.asExpression().code)) report(value.loc, what);
    } else if (value.isList()) {
      for (const ir::Value& item : std::get<ir::List>(value.data)) check(item, what);
    } else if (value.isMap()) {
      for (const ir::MapEntry& entry : std::get<ir::Map>(value.data)) check(entry.value, what);
    }
  }

  bool clean() const { return clean_; }

 private:
  void report(SourceLoc loc, const std::string& what) {
    diags_.emit(DiagKind::PythonCodeInCpp, loc, what, state_);
    clean_ = false;
  }

  DiagnosticEmitter& diags_;
  const std::string& state_;
  bool clean_ = true;
};

}  // namespace

bool checkNoPythonLambdas(const ir::Module& module, DiagnosticEmitter& diags) {
  bool clean = true;
  for (ir::StateId id : module.preorder()) {
    const ir::State& state = module.state(id);
    LambdaChecker checker(diags, state.name.text);
    for (const ir::Argument& callback : state.callbacks) {
      checker.check(callback.value, "callback `" + callback.key.text + "`");
    }
    for (const ir::Argument& entry : state.userdata) {
      checker.check(entry.value, "userdata `" + entry.key.text + "`");
    }
    clean = clean && checker.clean();
  }
  return clean;
}

generator::TemplatePath templatePath(const std::vector<std::string>& template_dirs) {
  return {template_dirs, {"cpp/"}, templates::builtinTemplates()};
}

std::optional<std::vector<OutputFile>> emitCpp(const ir::Module& module, EmitContext& context) {
  if (!checkNoPythonLambdas(module, context.diags)) return std::nullopt;
  generator::TemplatePath path = templatePath(context.options.template_dirs);
  generator::ValueConverter converter;
  auto env = std::make_unique<tmpl::Environment>(path.dirs, path.builtin_sets, path.builtins);
  registerCppExtensions(*env, converter, context.options.comments);
  const std::optional<LibraryNames>& library = context.options.library;
  env->addGlobal("cpp_library", libraryGlobal(library));
  generator::GeneratorContext generator_context{
      *env, converter, context.sources, context.diags, path, skipBlocks(context.options)};
  std::optional<std::string> code = generator::generate(module, generator_context);
  if (!code) return std::nullopt;
  if (!library) return std::vector<OutputFile>{{"", std::move(*code)}};
  std::optional<std::string> header = renderLibraryHeader(module, *env, converter, path, context);
  if (!header) return std::nullopt;
  return std::vector<OutputFile>{{library->header, std::move(*header)},
                                 {library->source, std::move(*code)}};
}

}  // namespace smachac::backends::cpp
