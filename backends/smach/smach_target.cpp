// The SMACH target: environment, skip blocks, generator, output file.
#include "backends/smach/smach_target.h"

#include <utility>

#include "backends/generator/generator.h"
#include "backends/smach/python_extensions.h"
#include "templates/builtin_templates.h"

namespace smachac::backends::smach {

generator::TemplatePath templatePath(const std::vector<std::string>& template_dirs) {
  return {template_dirs, {"smach/", "smach_ros/"}, templates::builtinTemplates()};
}

std::unique_ptr<tmpl::Environment> makeEnvironment(const generator::TemplatePath& path,
                                                   const generator::ValueConverter& converter,
                                                   bool include_comments) {
  auto env = std::make_unique<tmpl::Environment>(path.dirs, path.builtin_sets, path.builtins);
  registerPythonExtensions(*env, converter, include_comments);
  return env;
}

std::optional<std::vector<OutputFile>> emitSmach(ir::Module&& module, EmitContext& context) {
  generator::TemplatePath path = templatePath(context.options.template_dirs);
  generator::ValueConverter converter;
  std::unique_ptr<tmpl::Environment> env =
      makeEnvironment(path, converter, context.options.comments);
  generator::GeneratorContext generator_context{
      *env,          converter, context.sources,
      context.diags, path,      optionalBlocksSkipped(context.options)};
  std::optional<std::string> code = generator::generate(std::move(module), generator_context);
  if (!code) return std::nullopt;
  return std::vector<OutputFile>{{"", std::move(*code)}};
}

}  // namespace smachac::backends::smach
