// Changes to the editor's files as the protocol carries them. Rules:
//   * a change of a text is the fewest edits that turn it into the new text: the runs of
//     lines that differ (a Myers diff; past kMaxDiffSteps differing lines, one edit for
//     everything between the common first and last lines); a line replaced by one line is
//     narrowed to the bytes that differ, never splitting a UTF-8 sequence or a CRLF line
//     break; the text outside the edits is untouched
//   * a WorkspaceEdit uses `documentChanges` (TextDocumentEdits with the document's version,
//     CreateFile operations) when the client supports them, else the `changes` map
//   * a created file needs the client's `create` resource operation: without it the edit
//     cannot be made (canCreateFiles tells the callers, which then offer nothing)
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsp/json_rpc.h"
#include "lsp/positions.h"

namespace smachac::lsp {

/// Differing lines beyond which the diff gives up being minimal.
inline constexpr size_t kMaxDiffSteps = 1000;

struct TextEdit {
  Range range;
  std::string new_text;
  friend bool operator==(const TextEdit&, const TextEdit&) = default;
};

/// The edits that turn `before` into `after`, in document order (ranges in `before`).
std::vector<TextEdit> diffEdits(std::string_view before, std::string_view after);

Json toJson(const TextEdit& edit);

/// What the client can apply (its `workspace.workspaceEdit` capabilities).
struct EditSupport {
  bool document_changes = false;
  bool create_files = false;
};

EditSupport editSupport(const Json& client_capabilities);

/// A WorkspaceEdit being put together: created files and edited documents, in order.
class WorkspaceEdit {
 public:
  explicit WorkspaceEdit(EditSupport support) : support_(support) {}

  bool canCreateFiles() const { return support_.document_changes && support_.create_files; }
  /// A new empty file (only when canCreateFiles).
  void createFile(const std::string& uri);
  /// Edits of a document; `version` is the one they were computed on (none: a file that is
  /// not open, or was just created).
  void editDocument(const std::string& uri, std::optional<int64_t> version,
                    std::vector<TextEdit> edits);

  Json toJson() const;

 private:
  struct Change {
    std::string uri;
    bool create = false;
    std::optional<int64_t> version;
    std::vector<TextEdit> edits;
  };

  EditSupport support_;
  std::vector<Change> changes_;
};

}  // namespace smachac::lsp
