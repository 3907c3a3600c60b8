// Finding and analysing the closed scripts that include a changed sub-script.
#include "lsp/closed_scripts.h"

#include <algorithm>
#include <filesystem>

#include "frontend/yaml_loader.h"
#include "ir/support/file_text.h"
#include "lsp/uri.h"

namespace smachac::lsp {
namespace {

namespace fs = std::filesystem;

bool skippedFolder(const fs::path& folder) {
  std::string name = folder.filename().string();
  return name.starts_with('.') || name == "node_modules" || name.starts_with("build");
}

bool isYamlFile(const fs::directory_entry& entry) {
  std::error_code ec;
  std::string extension = entry.path().extension().string();
  return (extension == ".yml" || extension == ".yaml") && entry.is_regular_file(ec);
}

void collectYamlFiles(const fs::path& root, std::vector<std::string>& out, size_t limit) {
  std::error_code ec;
  auto options = fs::directory_options::skip_permission_denied;
  for (fs::recursive_directory_iterator it(root, options, ec), end; !ec && it != end;
       it.increment(ec)) {
    if (out.size() >= limit) return;
    if (it->is_directory(ec) && skippedFolder(it->path())) {
      it.disable_recursion_pending();
    } else if (isYamlFile(*it)) {
      out.push_back(fs::weakly_canonical(it->path(), ec).string());
    }
  }
}

std::optional<std::string> readText(const std::string& path) {
  std::error_code ec;
  if (fs::file_size(path, ec) > frontend::kMaxScriptBytes || ec) return std::nullopt;
  return readFileText(path);
}

}  // namespace

void ClosedScripts::setRoots(std::vector<std::string> roots) {
  roots_ = std::move(roots);
  filesChanged();
}

void ClosedScripts::filesChanged() {
  files_.reset();
  reads_.clear();
}

const std::vector<std::string>& ClosedScripts::files() {
  if (!files_) {
    files_.emplace();
    for (const std::string& root : roots_) collectYamlFiles(root, *files_, kMaxFiles);
    std::sort(files_->begin(), files_->end());
    files_->erase(std::unique(files_->begin(), files_->end()), files_->end());
  }
  return *files_;
}

bool ClosedScripts::mayRead(const std::string& file, const std::string& canonical_path) {
  auto known = reads_.find(file);
  if (known != reads_.end()) return known->second.contains(canonical_path);
  std::optional<std::string> text = readText(file);
  return text && text->find(fs::path(canonical_path).stem().string()) != std::string::npos;
}

std::vector<std::unique_ptr<Analysis>> ClosedScripts::includersOf(const std::string& canonical_path,
                                                                  const DocumentStore& documents,
                                                                  const Settings& settings) {
  std::vector<std::unique_ptr<Analysis>> analyses;
  for (const std::string& file : files()) {
    if (file == canonical_path || documents.overlay().contains(file)) continue;
    if (!mayRead(file, canonical_path)) continue;
    std::optional<std::string> text = readText(file);
    if (!text) continue;
    Document document{uriFromPath(file), file, file, std::move(*text), Analysis::kNotOpen};
    std::unique_ptr<Analysis> analysis = analyze(document, settings, documents.overlay());
    reads_[file] = analysis->dependencies;
    if (analysis->is_script && analysis->dependencies.contains(canonical_path)) {
      analyses.push_back(std::move(analysis));
    }
  }
  return analyses;
}

}  // namespace smachac::lsp
