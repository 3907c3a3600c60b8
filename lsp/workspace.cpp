// Keeping analyses up to date.
#include "lsp/workspace.h"

#include <algorithm>

namespace smachac::lsp {

void Workspace::setSettings(Settings settings) {
  if (settings == settings_) return;
  settings_ = std::move(settings);
  markAll();
}

void Workspace::opened(const std::string& uri) {
  markStale(uri);
  markAll();
}

void Workspace::changed(const std::string& uri) {
  markStale(uri);
  if (const Document* document = documents_.find(uri)) {
    if (!document->canonical_path.empty()) markDependents(document->canonical_path);
  }
}

void Workspace::closed(const std::string& uri) {
  analyses_.erase(uri);
  std::erase(stale_, uri);
  closed_.push_back(uri);
  markAll();
}

void Workspace::filesChanged() { markAll(); }

const Analysis* Workspace::analysis(const std::string& uri) {
  const Document* document = documents_.find(uri);
  if (!document) return nullptr;
  std::unique_ptr<Analysis>& slot = analyses_[uri];
  if (!slot) slot = analyze(*document, settings_, documents_.overlay());
  return slot.get();
}

std::vector<std::string> Workspace::takeStale() { return std::exchange(stale_, {}); }

std::vector<std::string> Workspace::takeClosed() { return std::exchange(closed_, {}); }

void Workspace::markAll() {
  for (const Document* document : documents_.all()) markStale(document->uri);
}

void Workspace::markDependents(const std::string& canonical_path) {
  for (const Document* document : documents_.all()) {
    auto it = analyses_.find(document->uri);
    if (it == analyses_.end() || !it->second) continue;
    if (it->second->dependencies.contains(canonical_path)) markStale(document->uri);
  }
}

void Workspace::markStale(const std::string& uri) {
  analyses_.erase(uri);
  if (std::find(stale_.begin(), stale_.end(), uri) == stale_.end()) stale_.push_back(uri);
}

}  // namespace smachac::lsp
