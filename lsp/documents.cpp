// Document texts and the incremental changes to them.
#include "lsp/documents.h"

#include <filesystem>

#include "lsp/positions.h"
#include "lsp/uri.h"

namespace smachac::lsp {
namespace {

std::string canonicalPath(const std::string& path) {
  std::error_code ec;
  std::string canonical = std::filesystem::weakly_canonical(path, ec).string();
  return ec ? path : canonical;
}

/// Applies one TextDocumentContentChangeEvent; false when it is malformed.
bool applyChange(std::string& text, const Json& change) {
  if (!change.is_object() || !change.contains("text") || !change["text"].is_string()) {
    return false;
  }
  const std::string& replacement = change["text"].get_ref<const std::string&>();
  if (!change.contains("range")) {
    text = replacement;
    return true;
  }
  LineIndex lines(text);
  const Json& range = change["range"];
  size_t begin = lines.offsetOf(positionFromJson(range.at("start")));
  size_t end = lines.offsetOf(positionFromJson(range.at("end")));
  if (end < begin) return false;
  text.replace(begin, end - begin, replacement);
  return true;
}

}  // namespace

const Document& DocumentStore::open(const std::string& uri, std::string text, int64_t version) {
  Document document{uri, uri, "", std::move(text), version};
  if (std::optional<std::string> path = pathFromUri(uri)) {
    document.name = *path;
    document.canonical_path = canonicalPath(*path);
    overlay_[document.canonical_path] = document.text;
  }
  return documents_[uri] = std::move(document);
}

bool DocumentStore::change(const std::string& uri, int64_t version, const Json& changes) {
  auto it = documents_.find(uri);
  if (it == documents_.end() || !changes.is_array()) return false;
  std::string text = it->second.text;
  for (const Json& change : changes) {
    if (!applyChange(text, change)) return false;
  }
  it->second.text = std::move(text);
  it->second.version = version;
  if (!it->second.canonical_path.empty()) overlay_[it->second.canonical_path] = it->second.text;
  return true;
}

void DocumentStore::close(const std::string& uri) {
  auto it = documents_.find(uri);
  if (it == documents_.end()) return;
  overlay_.erase(it->second.canonical_path);
  documents_.erase(it);
}

const Document* DocumentStore::find(const std::string& uri) const {
  auto it = documents_.find(uri);
  return it == documents_.end() ? nullptr : &it->second;
}

std::vector<const Document*> DocumentStore::all() const {
  std::vector<const Document*> out;
  for (const auto& [uri, document] : documents_) out.push_back(&document);
  return out;
}

}  // namespace smachac::lsp
