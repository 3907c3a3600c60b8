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
  const Document* document = documents_.find(uri);
  if (!document || document->canonical_path.empty()) return;
  markDependents(document->canonical_path);
  if (std::find(changed_files_.begin(), changed_files_.end(), document->canonical_path) ==
      changed_files_.end()) {
    changed_files_.push_back(document->canonical_path);
  }
}

void Workspace::closed(const std::string& uri) {
  analyses_.erase(uri);
  std::erase(stale_, uri);
  closed_.push_back(uri);
  markAll();
}

void Workspace::filesChanged() {
  closed_scripts_.filesChanged();
  markAll();
}

const Analysis* Workspace::analysis(const std::string& uri) {
  const Document* document = documents_.find(uri);
  if (!document) return nullptr;
  std::unique_ptr<Analysis>& slot = analyses_[uri];
  if (!slot) slot = analyze(*document, settings_, documents_.overlay());
  return slot.get();
}

std::vector<std::string> Workspace::takeStale() { return std::exchange(stale_, {}); }

std::vector<std::string> Workspace::takeClosed() { return std::exchange(closed_, {}); }

std::vector<std::unique_ptr<Analysis>> Workspace::takeClosedDependents() {
  std::vector<std::unique_ptr<Analysis>> analyses;
  for (const std::string& path : std::exchange(changed_files_, {})) {
    for (auto& analysis : closed_scripts_.includersOf(path, documents_, settings_)) {
      analyses.push_back(std::move(analysis));
    }
  }
  return analyses;
}

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
