// Quick fixes: which diagnostics, and the fix-its they carry.
#include "lsp/features/code_action_fixes.h"

#include <fmt/core.h>

#include <algorithm>

#include "lsp/features/diagnostics.h"
#include "refactor/flow_text.h"
#include "refactor/script_view.h"

namespace smachac::lsp {
namespace {

bool samePlace(const SourceLoc& a, const SourceLoc& b) {
  return a.file == b.file && a.line == b.line && a.column == b.column;
}

/// The byte range of a location's span in the document.
std::pair<size_t, size_t> spanOf(const Analysis& analysis, const SourceLoc& loc) {
  LineIndex lines = analysis.lines();
  Range range = lines.rangeOf(loc);
  return {lines.offsetOf(range.start), lines.offsetOf(range.end)};
}

/// Whether a scalar or mapping key of the YAML tree is written at `loc` (a name inside an
/// expression is not).
bool isYamlScalarAt(const ir::Value& node, const SourceLoc& loc, int depth = 0) {
  if (depth > 512) return false;
  if (node.isList()) {
    for (const ir::Value& item : node.asList()) {
      if (isYamlScalarAt(item, loc, depth + 1)) return true;
    }
    return false;
  }
  if (!node.isMap()) return samePlace(node.loc, loc);
  for (const ir::MapEntry& entry : node.asMap()) {
    if (samePlace(entry.key_loc, loc) || isYamlScalarAt(entry.value, loc, depth + 1)) return true;
  }
  return false;
}

char quoteOf(std::string_view text) {
  bool quoted = text.size() >= 2 && (text.front() == '\'' || text.front() == '"') &&
                text.back() == text.front();
  return quoted ? text.front() : '\0';
}

/// How the fix-it is written in place of `old_text`: inside an expression as it is; as a
/// YAML scalar in the quotes `old_text` has (when it needs no escapes), else as flow YAML.
std::string replacementText(const FixContext& fix, std::string_view old_text) {
  const std::string& name = *fix.diagnostic().fix;
  if (!fix.analysis().yaml || !isYamlScalarAt(*fix.analysis().yaml, fix.diagnostic().loc)) {
    return name;
  }
  char quote = quoteOf(old_text);
  if (quote && name.find_first_of("'\"\\") == std::string::npos) return quote + name + quote;
  return refactor::flowScalar(name);
}

/// Replaces the diagnostic's span with its fix-it.
void addReplacement(FixContext& fix) {
  const Diagnostic& d = fix.diagnostic();
  std::string old_text = fix.writtenText();
  if (!d.fix || old_text.empty()) return;
  auto [begin, end] = spanOf(fix.analysis(), d.loc);
  std::string text(fix.analysis().text());
  text.replace(begin, end - begin, replacementText(fix, old_text));
  std::string_view old_name = old_text;
  if (quoteOf(old_name)) old_name = old_name.substr(1, old_name.size() - 2);
  fix.offer(fmt::format("Change `{}` to `{}`", old_name, *d.fix), text, true);
}

}  // namespace

FixContext::FixContext(const ActionRequest& request, const Diagnostic& diagnostic,
                       std::vector<Json>& actions)
    : request_(request),
      diagnostic_(diagnostic),
      diagnostic_json_(diagnosticJson(request.analysis, diagnostic)),
      actions_(actions) {}

std::string FixContext::writtenText() const {
  if (!inDocument(diagnostic_.loc) || !diagnostic_.loc.hasLine()) return {};
  auto [begin, end] = spanOf(request_.analysis, diagnostic_.loc);
  return std::string(request_.analysis.text().substr(begin, end - begin));
}

void FixContext::offer(const std::string& title, std::string_view new_text, bool preferred) {
  bool offered = std::any_of(actions_.begin(), actions_.end(),
                             [&](const Json& action) { return action["title"] == title; });
  if (offered || new_text == request_.analysis.text()) return;
  Json action = codeActionJson(title, action_kind::kQuickFix, documentEdit(request_, new_text));
  action["diagnostics"] = Json::array({diagnostic_json_});
  if (preferred) action["isPreferred"] = true;
  actions_.push_back(std::move(action));
}

const ir::Name* nameAt(const std::vector<ir::Name>& names, const SourceLoc& loc) {
  auto it = std::find_if(names.begin(), names.end(),
                         [&](const ir::Name& name) { return samePlace(name.loc, loc); });
  return it == names.end() ? nullptr : &*it;
}

const ir::Value* listOwner(const FixContext& fix, const ir::State& state,
                           std::string_view longhand) {
  const ir::Value* mapping = stateMapping(fix.yaml(), state);
  if (!mapping || state.included_from.empty()) return mapping;
  return refactor::findKey(*mapping, longhand) ? mapping : nullptr;
}

std::vector<Json> quickFixes(const ActionRequest& request) {
  std::vector<Json> actions;
  const Analysis& analysis = request.analysis;
  LineIndex lines = analysis.lines();
  for (const Diagnostic& diagnostic : analysis.diagnostics) {
    if (!diagnostic.loc.hasFile() || diagnostic.loc.file != analysis.file) continue;
    if (!touches(lines.rangeOf(diagnostic.loc), request.range)) continue;
    FixContext fix(request, diagnostic, actions);
    addReplacement(fix);
    if (!analysis.module || !analysis.yaml) continue;
    addOutcomeFixes(fix);
    addInputKeyFixes(fix);
  }
  return actions;
}

}  // namespace smachac::lsp
