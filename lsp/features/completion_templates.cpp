// Templates and their meta blocks, as completion shows them.
#include "lsp/features/completion_templates.h"

#include "backends/meta/template_help.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::lsp {
namespace {

/// A meta field as text on one line, or "".
std::string fieldText(const tmpl::Value& map, std::string_view key) {
  const tmpl::Value* value = map.isDict() ? map.dict().findString(key) : nullptr;
  if (!value || value->isNone() || value->isUndefined()) return "";
  std::string text = tmpl::str(*value);
  for (char& c : text) c = c == '\n' ? ' ' : c;
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

/// `str`, or `float or str` for a list of types.
std::string typeText(const tmpl::Value& spec) {
  const tmpl::Value* type = spec.isDict() ? spec.dict().findString("type") : nullptr;
  if (!type || !type->isListOrTuple()) return fieldText(spec, "type");
  std::string text;
  for (const tmpl::Value& t : type->list().items()) {
    text += (text.empty() ? "" : " or ") + tmpl::str(t);
  }
  return text;
}

/// The first sentence of `text` (its full stop, not counting "e.g." and "i.e.").
std::string firstSentence(const std::string& text) {
  for (size_t end = text.find(". "); end != std::string::npos; end = text.find(". ", end + 1)) {
    std::string_view before = std::string_view(text).substr(0, end);
    if (!before.ends_with("e.g") && !before.ends_with("i.e")) return text.substr(0, end + 1);
  }
  return text;
}

/// The meta block's `variables`: `{var: spec}` required, `[{var: spec}]` optional, a longer
/// list a choice, `{heading: [...]}` a group.
class VariableReader {
 public:
  explicit VariableReader(std::vector<TemplateVariableInfo>& out) : out_(out) {}

  void entries(const tmpl::Value& list) {
    if (!list.isListOrTuple()) return;
    for (const tmpl::Value& entry : list.list().items()) this->entry(entry);
  }

 private:
  void entry(const tmpl::Value& entry) {
    if (entry.isDict()) return dict(entry, true, false);
    if (!entry.isListOrTuple()) return;
    bool choice = entry.list().items().size() > 1;
    for (const tmpl::Value& option : entry.list().items()) {
      if (option.isDict()) dict(option, false, choice);
    }
  }

  void dict(const tmpl::Value& dict, bool required, bool alternative) {
    for (const auto& [key, spec] : dict.dict().entries()) {
      if (spec.isListOrTuple()) {
        entries(spec);
        continue;
      }
      out_.push_back(
          {tmpl::str(key), fieldText(spec, "description"), typeText(spec), required, alternative});
    }
  }

  std::vector<TemplateVariableInfo>& out_;
};

/// Outcomes are names, or `{name: {description}}`.
std::vector<std::string> outcomesOf(const tmpl::Value& meta) {
  std::vector<std::string> outcomes;
  const tmpl::Value* list = meta.dict().findString("outcomes");
  if (!list || !list->isListOrTuple()) return outcomes;
  for (const tmpl::Value& outcome : list->list().items()) {
    if (outcome.isString()) outcomes.push_back(outcome.s());
    if (outcome.isDict() && outcome.dict().size() == 1) {
      outcomes.push_back(tmpl::str(outcome.dict().entries().front().first));
    }
  }
  return outcomes;
}

TemplateInfo infoOf(std::string name, const tmpl::Value& meta) {
  TemplateInfo info;
  info.name = std::move(name);
  info.description = fieldText(meta, "description");
  info.summary = firstSentence(info.description);
  info.type = fieldText(meta, "type");
  if (const tmpl::Value* variables = meta.dict().findString("variables")) {
    VariableReader(info.variables).entries(*variables);
  }
  info.outcomes = outcomesOf(meta);
  return info;
}

}  // namespace

TemplateLibrary::TemplateLibrary(const std::string& target,
                                 const std::vector<std::string>& template_dirs)
    : path_(backends::targetTemplatePath(target, template_dirs)),
      env_(backends::targetEnvironment(target, path_, converter_)) {}

TemplateLibrary::~TemplateLibrary() = default;

std::vector<std::string> TemplateLibrary::names() const { return generator::templateNames(path_); }

std::optional<TemplateInfo> TemplateLibrary::find(std::string_view name) {
  std::optional<std::string> resolved = env_->resolveScriptTemplate(name);
  if (!resolved) return std::nullopt;
  try {
    tmpl::Value meta = backends::templateMeta(*env_, *resolved);
    if (meta.isDict()) return infoOf(std::string(name), meta);
  } catch (const std::exception&) {
    // No meta block, or one that does not parse: the template is known by its name.
  }
  TemplateInfo info;
  info.name = std::string(name);
  return info;
}

}  // namespace smachac::lsp
