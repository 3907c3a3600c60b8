// The quick fixes of textDocument/codeAction: one or more per diagnostic of the document
// that the request's range touches, each naming that diagnostic. Only problems located in
// the document itself are fixed here (a sub-script's are fixed in the sub-script). Fixes:
//   * a diagnostic with a fix-it (Diagnostic::fix, a "did you mean"): replace its span
//   * code_action_outcome_fixes.cpp: transitions and outcomes
//   * code_action_key_fixes.cpp: userdata keys missing from `input_keys`
// A fix that cannot be written in the script's style (code_action_yaml.h) is not offered.
#pragma once

#include <string>
#include <vector>

#include "ir/module.h"
#include "ir/support/diagnostic.h"
#include "lsp/features/code_action.h"
#include "lsp/features/code_action_yaml.h"

namespace smachac::lsp {

/// The quick fixes for the diagnostics in the request's range.
std::vector<Json> quickFixes(const ActionRequest& request);

/// What the fixes of one diagnostic share.
class FixContext {
 public:
  FixContext(const ActionRequest& request, const Diagnostic& diagnostic,
             std::vector<Json>& actions);

  const Diagnostic& diagnostic() const { return diagnostic_; }
  const Analysis& analysis() const { return request_.analysis; }
  /// The document's text at the diagnostic's span.
  std::string writtenText() const;
  const ir::Module& module() const { return *request_.analysis.module; }
  const ir::Value& yaml() const { return *request_.analysis.yaml; }
  /// Whether a location is in the document.
  bool inDocument(const SourceLoc& loc) const { return loc.file == request_.analysis.file; }

  /// A new edit of the document's text.
  YamlEdit edit() const { return YamlEdit(request_.analysis.text()); }
  /// Offers a fix that turns the text into `new_text` (once per title).
  void offer(const std::string& title, std::string_view new_text, bool preferred = false);

  /// The first state in document order for which `matches` holds, or nullptr.
  template <typename Predicate>
  const ir::State* findState(Predicate matches) const {
    for (ir::StateId id : module().preorder()) {
      if (matches(module().state(id))) return &module().state(id);
    }
    return nullptr;
  }

 private:
  const ActionRequest& request_;
  const Diagnostic& diagnostic_;
  Json diagnostic_json_;
  std::vector<Json>& actions_;
};

/// The one of `names` written at `loc`, or nullptr.
const ir::Name* nameAt(const std::vector<ir::Name>& names, const SourceLoc& loc);

/// The mapping of `state` in the document when `longhand` may be added to it: a state
/// included from a sub-script takes that key from the sub-script unless its caller gives it,
/// and adding it to the caller would replace the sub-script's list, not extend it.
const ir::Value* listOwner(const FixContext& fix, const ir::State& state,
                           std::string_view longhand);

void addOutcomeFixes(FixContext& fix);
void addInputKeyFixes(FixContext& fix);

}  // namespace smachac::lsp
