// listTemplates (template_list.h).
#include "tools/smachac/template_list.h"

#include <memory>
#include <string_view>

#include "backends/meta/template_help.h"
#include "backends/tmpl/values/value_convert.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::driver {
namespace {

constexpr size_t kSummaryWidth = 70;

/// `text` cut at a space to at most kSummaryWidth characters, with "..." when cut.
std::string shortened(std::string text) {
  while (!text.empty() && text.back() == ' ') text.pop_back();
  if (text.size() <= kSummaryWidth) return text;
  size_t cut = text.rfind(' ', kSummaryWidth - 3);
  text.resize(cut == std::string::npos || cut == 0 ? kSummaryWidth - 3 : cut);
  return text + "...";
}

/// Where the first sentence ends (its full stop), not counting "e.g." and "i.e.".
size_t sentenceEnd(std::string_view text) {
  for (size_t end = text.find(". "); end != std::string_view::npos;
       end = text.find(". ", end + 1)) {
    std::string_view before = text.substr(0, end);
    if (!before.ends_with("e.g") && !before.ends_with("i.e")) return end;
  }
  return std::string_view::npos;
}

/// The first sentence of a template's meta description, on one line; "" without one.
std::string summary(tmpl::Environment& env, const std::string& name) {
  std::optional<std::string> resolved = env.resolveScriptTemplate(name);
  if (!resolved) return "";
  try {
    std::optional<std::string> meta = env.metaBlock(*resolved);
    if (!meta) return "";
    tmpl::Value parsed = tmpl::parseYaml(*meta, *resolved + " (meta block)");
    const tmpl::Value* description =
        parsed.isDict() ? parsed.dict().findString("description") : nullptr;
    if (!description || !description->isString()) return "";
    std::string text = tmpl::str(*description);
    for (char& c : text) c = c == '\n' ? ' ' : c;
    size_t end = sentenceEnd(text);
    if (end != std::string::npos) text.resize(end + 1);
    return shortened(text);
  } catch (const tmpl::TemplateError&) {
    return "(its meta block does not parse)";
  }
}

}  // namespace

void listTemplates(std::ostream& out, const std::string& target,
                   const std::vector<std::string>& template_dirs, const HelpStyle& style) {
  generator::TemplatePath path = backends::targetTemplatePath(target, template_dirs);
  generator::ValueConverter converter;
  std::unique_ptr<tmpl::Environment> env = backends::targetEnvironment(target, path, converter);
  out << style.title << target << " templates:" << style.reset << "\n";
  for (const std::string& name : generator::templateNames(path)) {
    out << "  " << style.name << name << style.reset;
    std::string text = summary(*env, name);
    if (!text.empty()) out << std::string(name.size() < 28 ? 28 - name.size() : 1, ' ') << text;
    out << "\n";
  }
}

}  // namespace smachac::driver
