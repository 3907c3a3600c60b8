// Template lookup in memory, directories and the embedded built-in sets (see loader.h).
#include "backends/tmpl/loader.h"

#include <algorithm>

#include "backends/tmpl/error.h"
#include "backends/tmpl/template_files.h"
#include "ir/support/file_text.h"

namespace smachac::tmpl {

std::optional<std::string> normalizeTemplateName(std::string_view name) {
  std::string out;
  size_t start = 0;
  while (start <= name.size()) {
    size_t end = name.find('/', start);
    if (end == std::string_view::npos) end = name.size();
    std::string_view piece = name.substr(start, end - start);
    if (piece == ".." || piece.find('\\') != std::string_view::npos) return std::nullopt;
    if (!piece.empty() && piece != ".") {
      if (!out.empty()) out += '/';
      out += piece;
    }
    start = end + 1;
  }
  if (out.empty()) return std::nullopt;
  return out;
}

Loader::Loader(std::vector<std::string> dirs, std::vector<std::string> builtin_sets,
               std::span<const EmbeddedFile> builtins)
    : dirs_(std::move(dirs)), builtin_sets_(std::move(builtin_sets)) {
  for (std::string& set : builtin_sets_) {
    if (!set.empty() && set.back() != '/') set += '/';
  }
  builtins_.assign(builtins.begin(), builtins.end());
  // Sorted, and the first of equal paths kept (what a map's emplace kept). The build's table
  // comes sorted: checking costs a tenth of sorting it again for every loader.
  auto before = [](const EmbeddedFile& a, const EmbeddedFile& b) { return a.path < b.path; };
  auto not_before = [](const EmbeddedFile& a, const EmbeddedFile& b) { return !(a.path < b.path); };
  if (std::adjacent_find(builtins_.begin(), builtins_.end(), not_before) == builtins_.end()) return;
  std::stable_sort(builtins_.begin(), builtins_.end(), before);
  auto duplicate = [](const EmbeddedFile& a, const EmbeddedFile& b) { return a.path == b.path; };
  builtins_.erase(std::unique(builtins_.begin(), builtins_.end(), duplicate), builtins_.end());
}

const EmbeddedFile* Loader::findBuiltin(std::string_view path) const {
  auto it = std::lower_bound(builtins_.begin(), builtins_.end(), path,
                             [](const EmbeddedFile& e, std::string_view p) { return e.path < p; });
  return it != builtins_.end() && it->path == path ? &*it : nullptr;
}

void Loader::addMemory(std::string name, std::string text) {
  memory_.insert_or_assign(std::move(name), std::move(text));
}

std::optional<TemplateSource> Loader::load(std::string_view raw_name) const {
  if (auto it = memory_.find(raw_name); it != memory_.end())
    return TemplateSource{it->first, it->second, false, {}, {}, {}};
  std::optional<std::string> name = normalizeTemplateName(raw_name);
  if (!name) return std::nullopt;
  for (const std::string& dir : dirs_) {
    std::string path = joinTemplatePath(dir, *name);
    if (!isRegularTemplateFile(path)) continue;
    std::optional<std::string> text = readFileText(path);
    if (!text) fail("cannot read template file `" + path + "`");
    return TemplateSource{lexicallyNormal(std::move(path)), std::move(*text), false, {}, {}, {}};
  }
  for (const std::string& set : builtin_sets_) {
    if (const EmbeddedFile* file = findBuiltin(set + *name)) {
      std::string origin = "<builtin>/" + std::string(file->path);
      return TemplateSource{std::move(origin), {}, true, file->content, file->tokens, file->image};
    }
  }
  return std::nullopt;
}

bool Loader::exists(std::string_view raw_name) const {
  if (memory_.count(raw_name)) return true;
  std::optional<std::string> name = normalizeTemplateName(raw_name);
  if (!name) return false;
  for (const std::string& dir : dirs_) {
    if (isRegularTemplateFile(joinTemplatePath(dir, *name))) return true;
  }
  return std::any_of(builtin_sets_.begin(), builtin_sets_.end(),
                     [&](const std::string& set) { return findBuiltin(set + *name) != nullptr; });
}

// Picks `base`, `base.tpl.py`, `base.tpl`, then the first `base.tpl.<ext>` among `entries`.
std::optional<std::string> Loader::resolveIn(const std::vector<std::string_view>& entries,
                                             std::string_view base) const {
  auto has = [&](const std::string& n) {
    return std::find(entries.begin(), entries.end(), n) != entries.end();
  };
  std::string b(base);
  for (const std::string& candidate : {b, b + ".tpl.py", b + ".tpl"}) {
    if (has(candidate)) return candidate;
  }
  std::string prefix = b + ".tpl.";
  std::optional<std::string_view> best;
  for (std::string_view e : entries) {
    if (e.size() <= prefix.size() || !e.starts_with(prefix)) continue;
    std::string_view ext = e.substr(prefix.size());
    bool word = std::all_of(ext.begin(), ext.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
    if (word && (!best || e < *best)) best = e;
  }
  if (!best) return std::nullopt;
  return std::string(*best);
}

std::optional<std::string> Loader::resolveScriptName(std::string_view raw_name) const {
  std::optional<std::string> name = normalizeTemplateName(raw_name);
  if (!name) return std::nullopt;
  size_t slash = name->rfind('/');
  std::string subdir = slash == std::string::npos ? "" : name->substr(0, slash + 1);
  std::string base = slash == std::string::npos ? *name : name->substr(slash + 1);
  std::vector<std::string_view> memory_entries;
  for (const auto& [n, text] : memory_) {
    if (n.compare(0, subdir.size(), subdir) == 0 &&
        n.find('/', subdir.size()) == std::string::npos) {
      memory_entries.push_back(std::string_view(n).substr(subdir.size()));
    }
  }
  if (auto found = resolveIn(memory_entries, base)) return subdir + *found;
  for (const std::string& dir : dirs_) {
    const std::vector<std::string>& files = listings_.regularFilesIn(joinTemplatePath(dir, subdir));
    if (auto found = resolveIn({files.begin(), files.end()}, base)) return subdir + *found;
  }
  for (const std::string& set : builtin_sets_) {
    std::string prefix = set + subdir;
    std::vector<std::string_view> entries;  // views of the built-in table's paths
    auto from =
        std::lower_bound(builtins_.begin(), builtins_.end(), std::string_view(prefix),
                         [](const EmbeddedFile& e, std::string_view p) { return e.path < p; });
    for (auto it = from; it != builtins_.end() && it->path.starts_with(prefix); ++it) {
      std::string_view rest = it->path.substr(prefix.size());
      if (rest.find('/') == std::string_view::npos) entries.emplace_back(rest);
    }
    if (auto found = resolveIn(entries, base)) return subdir + *found;
  }
  return std::nullopt;
}

std::string Loader::searchDescription() const {
  std::string out;
  auto add = [&](const std::string& s) {
    if (!out.empty()) out += ", ";
    out += s;
  };
  for (const std::string& dir : dirs_) add("`" + dir + "`");
  for (const std::string& set : builtin_sets_) add("built-in `" + set + "`");
  if (out.empty()) out = "no template directories";
  return out;
}

}  // namespace smachac::tmpl
