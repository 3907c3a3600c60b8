// textDocument/codeAction: the quick fixes of the diagnostics in the range
// (code_action_fixes.h), then the refactorings (code_action_refactors.h). Rules:
//   * CodeAction literals only: a client without `codeActionLiteralSupport` gets none
//   * `context.only` keeps the actions of those kinds and their sub-kinds (`refactor` keeps
//     refactor.rewrite and refactor.extract)
//   * no actions for a document that is not open, not a script, or has no analysis yet;
//     a range past the end of the text is clamped to it
#include <algorithm>

#include "lsp/features/code_action_fixes.h"
#include "lsp/features/code_action_refactors.h"
#include "lsp/features/features.h"

namespace smachac::lsp {
namespace {

/// The value at `pointer` in `json`, or null.
Json valueAt(const Json& json, const char* pointer) {
  Json::json_pointer path(pointer);
  return json.contains(path) ? json.at(path) : Json();
}

bool supportsLiterals(const Json& client_capabilities) {
  return valueAt(client_capabilities, "/textDocument/codeAction/codeActionLiteralSupport")
      .is_object();
}

/// Whether `context.only` lets actions of `kind` through.
bool wanted(const Json& only, std::string_view kind) {
  if (!only.is_array()) return true;
  return std::any_of(only.begin(), only.end(), [&](const Json& prefix) {
    if (!prefix.is_string()) return false;
    const std::string& p = prefix.get_ref<const std::string&>();
    return kind == p || (kind.starts_with(p) && kind.size() > p.size() && kind[p.size()] == '.');
  });
}

Range rangeFromJson(const Json& json) {
  Range range{positionFromJson(json.at("start")), positionFromJson(json.at("end"))};
  if (range.end < range.start) std::swap(range.start, range.end);
  return range;
}

}  // namespace

Json codeAction(Workspace& workspace, const Json& params) {
  std::string uri = params.at("textDocument").at("uri").get<std::string>();
  Range range = rangeFromJson(params.at("range"));
  Json only = valueAt(params, "/context/only");
  const Analysis* analysis = workspace.analysis(uri);
  const Document* document = workspace.documents().find(uri);
  Json actions = Json::array();
  if (!analysis || !document || !analysis->is_script ||
      !supportsLiterals(workspace.clientCapabilities())) {
    return actions;
  }
  LineIndex lines = analysis->lines();
  range = {lines.positionOf(lines.offsetOf(range.start)),
           lines.positionOf(lines.offsetOf(range.end))};
  ActionRequest request{*analysis,
                        *document,
                        range,
                        editSupport(workspace.clientCapabilities()),
                        workspace.settings(),
                        workspace.documents().overlay()};
  if (wanted(only, action_kind::kQuickFix)) {
    for (Json& action : quickFixes(request)) actions.push_back(std::move(action));
  }
  RefactorKinds kinds{wanted(only, action_kind::kRewrite), wanted(only, action_kind::kExtract)};
  for (Json& action : refactorActions(request, kinds)) actions.push_back(std::move(action));
  return actions;
}

}  // namespace smachac::lsp
