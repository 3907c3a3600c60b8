// What the code actions of one textDocument/codeAction request share, and how an action is
// written: a CodeAction literal with a title, a kind, the diagnostics it fixes (quick fixes)
// and a WorkspaceEdit made of the fewest text edits (lsp/workspace_edit.h), so that the
// comments and layout of the script outside the change are untouched.
#pragma once

#include <string>
#include <string_view>

#include "lsp/analysis.h"
#include "lsp/documents.h"
#include "lsp/json_rpc.h"
#include "lsp/positions.h"
#include "lsp/settings.h"
#include "lsp/workspace_edit.h"

namespace smachac::lsp {

namespace action_kind {
inline constexpr std::string_view kQuickFix = "quickfix";
inline constexpr std::string_view kRewrite = "refactor.rewrite";
inline constexpr std::string_view kExtract = "refactor.extract";
}  // namespace action_kind

struct ActionRequest {
  const Analysis& analysis;
  const Document& document;
  Range range;  ///< the selection, or the cursor (an empty range)
  EditSupport support;
  const Settings& settings;
  const frontend::DocumentOverlay& overlay;
};

/// A CodeAction with `edit`.
Json codeActionJson(std::string_view title, std::string_view kind, const WorkspaceEdit& edit);

/// The edit of the request's document that turns its text into `new_text`.
WorkspaceEdit documentEdit(const ActionRequest& request, std::string_view new_text);

/// Whether two ranges share a position (touching ends count: a cursor at the end of a word
/// is on it).
bool touches(const Range& a, const Range& b);

}  // namespace smachac::lsp
