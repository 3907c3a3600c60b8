// Sub-script files around a document.
#include "lsp/features/completion_sub_scripts.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

namespace smachac::lsp {
namespace {

namespace fs = std::filesystem;

/// Whether the file's first line that is not blank or a comment is a list item.
bool looksLikeSubScript(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  for (int read = 0; read < 200 && std::getline(in, line); ++read) {
    size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    return line.compare(first, 2, "- ") == 0 || line.substr(first) == "-";
  }
  return false;
}

bool isHidden(const fs::path& path) { return path.filename().string().starts_with("."); }

class SubScriptFinder {
 public:
  explicit SubScriptFinder(fs::path document) : document_(std::move(document)) {}

  /// `shown`: how the files' paths start (empty for the document's own directory).
  void searchDirectory(const fs::path& dir, const fs::path& shown) {
    size_t looked_at = 0;
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      if (++looked_at > kMaxSubScriptFiles) return;
      if (isHidden(it->path()) || it.depth() >= 1) it.disable_recursion_pending();
      if (isHidden(it->path()) || !isCandidate(*it)) continue;
      fs::path relative = it->path().lexically_relative(dir);
      std::string name = fs::path(relative).replace_extension().generic_string();
      if (!found_.contains(name) && looksLikeSubScript(it->path())) {
        found_.emplace(name, (shown / relative).generic_string());
      }
    }
  }

  std::vector<SubScriptFile> files() const {
    std::vector<SubScriptFile> files;
    for (const auto& [name, path] : found_) files.push_back({name, path});
    return files;
  }

 private:
  bool isCandidate(const fs::directory_entry& entry) const {
    std::error_code ec;
    if (entry.path().extension() != ".yml" || !entry.is_regular_file(ec)) return false;
    return document_.empty() || !fs::equivalent(entry.path(), document_, ec);
  }

  fs::path document_;
  std::map<std::string, std::string> found_;  ///< by name
};

}  // namespace

std::vector<SubScriptFile> findSubScripts(const std::string& document_path,
                                          const std::vector<std::string>& script_dirs) {
  SubScriptFinder finder(document_path);
  fs::path own = fs::path(document_path).parent_path();
  finder.searchDirectory(own.empty() ? fs::path(".") : own, "");
  for (const std::string& dir : script_dirs) finder.searchDirectory(dir, dir);
  return finder.files();
}

}  // namespace smachac::lsp
