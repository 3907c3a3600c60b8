// Code action literals and the document edits they carry.
#include "lsp/features/code_action.h"

namespace smachac::lsp {

Json codeActionJson(std::string_view title, std::string_view kind, const WorkspaceEdit& edit) {
  return {{"title", title}, {"kind", kind}, {"edit", edit.toJson()}};
}

WorkspaceEdit documentEdit(const ActionRequest& request, std::string_view new_text) {
  WorkspaceEdit edit(request.support);
  edit.editDocument(request.analysis.uri, request.analysis.version,
                    diffEdits(request.analysis.text(), new_text));
  return edit;
}

bool touches(const Range& a, const Range& b) { return a.start <= b.end && b.start <= a.end; }

}  // namespace smachac::lsp
