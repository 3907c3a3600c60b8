// The template catalog and template file registration.
#include "backends/generator/template_catalog.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

#include "backends/tmpl/loader.h"
#include "backends/tmpl/template_files.h"
#include "ir/support/file_text.h"
#include "ir/support/suggest.h"

namespace smachac::generator {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kBuiltinPrefix = "<builtin>/";

/// `Foo` for `Foo.tpl`, `Foo.tpl.py` or `Foo.tpl.<word>`; nullopt for other files.
std::optional<std::string> scriptName(std::string_view file) {
  if (file.empty() || file.front() == '.') return std::nullopt;
  size_t pos = file.rfind(".tpl");
  while (pos != std::string_view::npos && pos > 0) {
    std::string_view rest = file.substr(pos + 4);
    bool word_ext = rest.size() > 1 && rest.front() == '.' &&
                    std::all_of(rest.begin() + 1, rest.end(), [](char c) {
                      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                    });
    if (rest.empty() || word_ext) return std::string(file.substr(0, pos));
    pos = file.rfind(".tpl", pos - 1);
  }
  return std::nullopt;
}

std::string withSlash(std::string set) {
  if (!set.empty() && set.back() != '/') set += '/';
  return set;
}

}  // namespace

std::vector<std::string> templateNames(const TemplatePath& path) {
  std::set<std::string> names;
  for (const std::string& dir : path.dirs) {
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      if (!it->is_regular_file(ec)) continue;
      if (auto n = scriptName(it->path().filename().string())) names.insert(*n);
    }
  }
  for (const std::string& raw_set : path.builtin_sets) {
    std::string set = withSlash(raw_set);
    for (const EmbeddedFile& file : path.builtins) {
      if (!file.path.starts_with(set)) continue;
      std::string_view rest = file.path.substr(set.size());
      if (rest.find('/') != std::string_view::npos) continue;
      if (auto n = scriptName(rest)) names.insert(*n);
    }
  }
  return {names.begin(), names.end()};
}

namespace {

bool plainName(std::string_view name) {
  if (name.empty() || name.find('\\') != std::string_view::npos) return false;
  size_t start = 0;
  while (start <= name.size()) {
    size_t end = std::min(name.find('/', start), name.size());
    std::string_view piece = name.substr(start, end - start);
    if (piece.empty() || piece == "." || piece == "..") return false;
    start = end + 1;
  }
  return true;
}

}  // namespace

std::optional<std::string> readTemplateSource(const TemplatePath& path, std::string_view name) {
  if (!plainName(name)) return std::nullopt;
  for (const std::string& dir : path.dirs) {
    std::string file = tmpl::joinTemplatePath(dir, name);
    if (tmpl::isRegularTemplateFile(file)) return readFileText(file);
  }
  for (const std::string& set : path.builtin_sets) {
    std::string full = withSlash(set) + std::string(name);
    for (const EmbeddedFile& file : path.builtins) {
      if (file.path == full) return std::string(file.content);
    }
  }
  return std::nullopt;
}

std::optional<std::string> builtinTemplatePath(const TemplatePath& path, std::string_view name) {
  std::optional<std::string> normal = tmpl::normalizeTemplateName(name);
  if (!normal) return std::nullopt;
  for (const std::string& dir : path.dirs) {
    if (tmpl::isRegularTemplateFile(tmpl::joinTemplatePath(dir, *normal))) return std::nullopt;
  }
  for (const std::string& set : path.builtin_sets) {
    std::string full = withSlash(set) + *normal;
    for (const EmbeddedFile& file : path.builtins) {
      if (file.path == full) return full;
    }
  }
  return std::nullopt;
}

std::string describePath(const TemplatePath& path) {
  std::string out;
  auto add = [&](const std::string& s) { out += (out.empty() ? "" : ", ") + s; };
  for (const std::string& dir : path.dirs) add("`" + dir + "`");
  for (const std::string& set : path.builtin_sets) add("built-in `" + withSlash(set) + "`");
  return out.empty() ? "no template directory" : out;
}

std::optional<std::string> closestTemplate(std::string_view name, const TemplatePath& path) {
  return closestMatch(name, templateNames(path));
}

std::string suggestTemplate(std::string_view name, const TemplatePath& path) {
  return didYouMean(closestTemplate(name, path));
}

SourceLoc TemplateFiles::locate(const tmpl::TemplateError& error) {
  auto it = files_.find(error.file());
  if (it == files_.end()) {
    uint32_t id = sources_.addFile(error.file(), text(error.file()).value_or(""));
    it = files_.emplace(error.file(), id).first;
  }
  return SourceLoc{it->second, static_cast<uint32_t>(std::max(error.line(), 0)),
                   static_cast<uint32_t>(std::max(error.column(), 0)), 1};
}

std::optional<std::string> TemplateFiles::text(const std::string& origin) const {
  if (origin.starts_with(kBuiltinPrefix)) {
    std::string_view path = std::string_view(origin).substr(kBuiltinPrefix.size());
    for (const EmbeddedFile& file : builtins_) {
      if (file.path == path) return std::string(file.content);
    }
    return std::nullopt;
  }
  return readFileText(origin);
}

}  // namespace smachac::generator
