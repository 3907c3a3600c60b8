// The C++ target: the lambda-language check, environment, generator, output file(s).
#include "backends/cpp/cpp_target.h"

#include <memory>

#include "backends/cpp/cpp_extensions.h"
#include "backends/cpp/cpp_library.h"
#include "backends/generator/generator.h"
#include "templates/builtin_templates.h"

namespace smachac::backends::cpp {

generator::TemplatePath templatePath(const std::vector<std::string>& template_dirs) {
  return {template_dirs, {"cpp/"}, templates::builtinTemplates()};
}

std::optional<std::vector<OutputFile>> emitCpp(ir::Module&& module, EmitContext& context) {
  generator::TemplatePath path = templatePath(context.options.template_dirs);
  generator::ValueConverter converter;
  auto env = std::make_unique<tmpl::Environment>(path.dirs, path.builtin_sets, path.builtins);
  registerCppExtensions(*env, converter, context.options.comments);
  const std::optional<LibraryNames>& library = context.options.library;
  env->addGlobal("cpp_library", libraryGlobal(library));
  generator::GeneratorContext generator_context{
      *env,          converter, context.sources,
      context.diags, path,      optionalBlocksSkipped(context.options)};
  std::optional<std::string> code = generator::generate(module, generator_context);
  if (!code) return std::nullopt;
  if (!library) return std::vector<OutputFile>{{"", std::move(*code)}};
  std::optional<std::string> header = renderLibraryHeader(module, *env, converter, path, context);
  if (!header) return std::nullopt;
  return std::vector<OutputFile>{{library->header, std::move(*header)},
                                 {library->source, std::move(*code)}};
}

}  // namespace smachac::backends::cpp
