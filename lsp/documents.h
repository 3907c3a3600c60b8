// The documents the editor has open: their text and version, kept in step with
// didOpen/didChange/didClose (full and incremental changes). A document's `name` is what
// diagnostics and the compiler call it: its path for a file URI, else the URI itself.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frontend/document_overlay.h"
#include "lsp/json_rpc.h"

namespace smachac::lsp {

struct Document {
  std::string uri;
  std::string name;            ///< the path, or the URI when it is not a file URI
  std::string canonical_path;  ///< empty for a document that is not a file
  std::string text;
  int64_t version = 0;
};

class DocumentStore {
 public:
  const Document& open(const std::string& uri, std::string text, int64_t version);
  /// Applies `contentChanges` in order; false (document unchanged) when a range is invalid
  /// or the document is not open.
  bool change(const std::string& uri, int64_t version, const Json& changes);
  void close(const std::string& uri);

  const Document* find(const std::string& uri) const;
  std::vector<const Document*> all() const;
  /// The open file documents by canonical path, for sub-script lookups.
  const frontend::DocumentOverlay& overlay() const { return overlay_; }

 private:
  std::map<std::string, Document> documents_;  ///< by URI
  frontend::DocumentOverlay overlay_;
};

}  // namespace smachac::lsp
