// The FlexBE target: environment, generator, file split, manual sections.
#include "backends/flexbe/flexbe_target.h"

#include "backends/flexbe/behavior_writer.h"
#include "backends/flexbe/manual_sections.h"
#include "backends/generator/generator.h"
#include "backends/smach/python_extensions.h"
#include "ir/support/file_text.h"
#include "templates/builtin_templates.h"

namespace smachac::backends::flexbe {
namespace {

constexpr std::string_view kFileMarker = "#@smachac-file ";

std::vector<std::string> skipBlocks(const EmitOptions& options) {
  std::vector<std::string> skip;
  if (!options.comments) skip.insert(skip.end(), {"upper_comments", "lower_comments"});
  return skip;
}

/// Keeps the manual sections of the files that already exist in the output directory.
bool keepManualSections(std::vector<OutputFile>& files, const EmitContext& context) {
  const std::string& dir = context.options.output;
  if (dir.empty() || dir == "-") return true;
  for (OutputFile& file : files) {
    std::optional<std::string> existing = readFileText(dir + "/" + file.name);
    if (!existing) continue;
    std::optional<std::string> merged = flexbe::keepManualSections(file.content, *existing);
    if (!merged) {
      context.diags.emit<DiagKind::FlexbeManualSectionBroken>(SourceLoc{}, dir + "/" + file.name);
      return false;
    }
    file.content = std::move(*merged);
  }
  return true;
}

}  // namespace

std::vector<OutputFile> splitFiles(std::string_view text) {
  std::vector<OutputFile> files;
  size_t at = 0;
  while (at < text.size()) {
    size_t line_end = text.find('\n', at);
    if (line_end == std::string_view::npos) line_end = text.size();
    std::string_view line = text.substr(at, line_end - at);
    size_t next = line_end < text.size() ? line_end + 1 : line_end;
    if (line.starts_with(kFileMarker)) {
      files.push_back({std::string(line.substr(kFileMarker.size())), ""});
    } else if (!files.empty()) {
      files.back().content.append(text.substr(at, next - at));
    }
    at = next;
  }
  for (OutputFile& file : files) {
    while (!file.content.empty() && file.content.back() == '\n') file.content.pop_back();
    file.content += '\n';
  }
  return files;
}

generator::TemplatePath templatePath(const std::vector<std::string>& template_dirs) {
  return {template_dirs, {"flexbe/"}, templates::builtinTemplates()};
}

std::optional<std::vector<OutputFile>> emitFlexbe(ir::Module&& module, EmitContext& context) {
  generator::TemplatePath path = templatePath(context.options.template_dirs);
  generator::ValueConverter converter;
  tmpl::Environment env(path.dirs, path.builtin_sets, path.builtins);
  smach::registerPythonExtensions(env, converter, context.options.comments);
  env.addGlobal("flexbe_ros", tmpl::Value::integer(context.options.flexbe_ros));
  generator::GeneratorContext generator_context{
      env, converter, context.sources, context.diags, path, skipBlocks(context.options)};
  std::optional<std::vector<std::string>> codes = writeBehaviors(module, generator_context);
  if (!codes) return std::nullopt;
  std::vector<OutputFile> files;
  for (const std::string& code : *codes) {
    for (OutputFile& file : splitFiles(code)) files.push_back(std::move(file));
  }
  if (!keepManualSections(files, context)) return std::nullopt;
  return files;
}

}  // namespace smachac::backends::flexbe
