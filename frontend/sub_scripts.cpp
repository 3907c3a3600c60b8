// Sub-script resolution, loading and shape checks.
#include "frontend/sub_scripts.h"

#include <fmt/core.h>

#include <filesystem>

#include "frontend/yaml_loader.h"

namespace smachac::frontend {
namespace {

namespace fs = std::filesystem;

std::string joinPath(const std::string& dir, const std::string& name) {
  if (dir.empty()) return fs::path(name).lexically_normal().string();
  return (fs::path(dir) / name).lexically_normal().string();
}

/// True when `name` climbs out of its directory (`../x`) and `canonical` is outside `dir`.
bool climbsOut(const std::string& name, const std::string& dir, const std::string& canonical) {
  bool has_parent_step = false;
  for (const fs::path& part : fs::path(name)) has_parent_step = has_parent_step || part == "..";
  if (!has_parent_step) return false;
  std::error_code ec;
  std::string base = fs::weakly_canonical(dir.empty() ? "." : dir, ec).string();
  return !canonical.starts_with(base + "/");
}

bool isRegularFile(const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

}  // namespace

std::vector<std::string> SubScriptLoader::candidates(const ir::Name& script) const {
  std::vector<std::string> names{script.text};
  if (!script.text.str().ends_with(".yml")) names.push_back(script.text + ".yml");
  std::vector<std::string> paths;
  if (fs::path(script.text.str()).is_absolute()) {
    for (const std::string& n : names) paths.push_back(n);
    return paths;
  }
  std::vector<std::string> dirs;
  dirs.push_back(fs::path(sources_.path(script.loc.file)).parent_path().string());
  dirs.insert(dirs.end(), search_dirs_.begin(), search_dirs_.end());
  for (const std::string& dir : dirs) {
    for (const std::string& n : names) paths.push_back(joinPath(dir, n));
  }
  return paths;
}

const std::string* SubScriptLoader::overlaid(const std::string& canonical) const {
  if (!overlay_) return nullptr;
  auto it = overlay_->find(canonical);
  return it == overlay_->end() ? nullptr : &it->second;
}

LoadedYaml SubScriptLoader::read(const std::string& path, const std::string& canonical,
                                 SourceLoc from) {
  const std::string* text = overlaid(canonical);
  if (!text) return loadYamlFile(path, from, sources_, diags_);
  uint32_t file = sources_.addFile(path, *text);
  return {file, parseYaml(file, sources_, diags_)};
}

std::optional<SubScriptState> SubScriptLoader::load(const ir::Name& script) {
  std::vector<std::string> tried = candidates(script);
  for (const std::string& path : tried) {
    std::error_code ec;
    std::string canonical = fs::weakly_canonical(path, ec).string();
    if (!overlaid(canonical) && !isRegularFile(path)) continue;
    auto it = cache_.find(canonical);
    if (it == cache_.end()) {
      LoadedYaml loaded = read(path, canonical, script.loc);
      if (loaded.file != 0) files_.push_back(loaded.file);
      it = cache_.emplace(canonical, Cached{loaded.file, std::move(loaded.root)}).first;
    }
    if (it->second.file != 0) sites_[it->second.file].push_back(script.loc);
    if (!it->second.root) return std::nullopt;
    std::string dir = fs::path(sources_.path(script.loc.file)).parent_path().string();
    if (climbsOut(script.text, dir, canonical)) {
      diags_.emit<DiagKind::SubScriptOutsideDir>(script.loc, script.text, path);
    }
    std::optional<SubScriptState> state = validate(it->second.file, *it->second.root);
    if (state) state->canonical_path = canonical;
    return state;
  }
  diags_.emit<DiagKind::SubScriptNotFound>(script.loc, script.text);
  for (const std::string& path : tried) diags_.note<DiagNoteKind::LookedFor>({}, path);
  return std::nullopt;
}

std::optional<SubScriptState> SubScriptLoader::validate(uint32_t file, const ir::Value& root) {
  std::string found = describeValue(root);
  if (root.isList() && root.asList().size() != 1) {
    found = fmt::format("a list of {} entries", root.asList().size());
  } else if (root.isList() && (!root.asList()[0].isMap() || root.asList()[0].asMap().size() != 1)) {
    found = fmt::format("a list holding {}", describeValue(root.asList()[0]));
    if (root.asList()[0].isMap()) {
      found = fmt::format("a list holding a mapping of {} keys", root.asList()[0].asMap().size());
    }
  } else if (root.isList()) {
    return SubScriptState{file, {}, root.asList()[0].asMap()[0]};
  }
  SourceLoc where = root.loc.hasFile() ? root.loc : SourceLoc{file, 1, 1, 1};
  diags_.emit<DiagKind::SubScriptNotOneState>(where, sources_.path(file), found);
  return std::nullopt;
}

}  // namespace smachac::frontend
