// Dependency files for build systems.
#include "tools/smachac/depfile.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <system_error>

namespace smachac::driver {
namespace {

namespace fs = std::filesystem;

std::string absolutePath(const std::string& path) {
  std::error_code error;
  fs::path absolute = fs::absolute(path, error);
  return error ? path : absolute.lexically_normal().string();
}

std::string escapeForMake(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

bool isHidden(const fs::path& path) {
  std::string name = path.filename().string();
  return !name.empty() && name[0] == '.';
}

void addTemplateFiles(const std::string& dir, std::set<std::string>& files) {
  std::error_code error;
  fs::recursive_directory_iterator it(dir, error), end;
  for (; !error && it != end; it.increment(error)) {
    if (isHidden(it->path())) {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) files.insert(absolutePath(it->path().string()));
  }
}

}  // namespace

std::string depfileText(const std::string& output, const ir::Module& module,
                        const SourceManager& sources,
                        const std::vector<std::string>& template_dirs) {
  std::vector<std::string> scripts;
  for (uint32_t file : module.files()) {
    std::string path = absolutePath(sources.path(file));
    if (std::find(scripts.begin(), scripts.end(), path) == scripts.end()) scripts.push_back(path);
  }
  std::set<std::string> templates;
  for (const std::string& dir : template_dirs) addTemplateFiles(dir, templates);
  std::string text = escapeForMake(absolutePath(output)) + ":";
  for (const std::string& path : scripts) text += " \\\n  " + escapeForMake(path);
  for (const std::string& path : templates) text += " \\\n  " + escapeForMake(path);
  return text + "\n";
}

}  // namespace smachac::driver
