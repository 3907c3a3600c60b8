// Finding templates, their meta blocks, and the cache copies of built-in ones.
#include "lsp/index_templates.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "backends/meta/template_help.h"
#include "backends/meta/template_meta.h"
#include "ir/support/file_text.h"
#include "ir/support/version.h"

namespace smachac::lsp {
namespace {

namespace fs = std::filesystem;

bool holds(const fs::path& path, std::string_view content) {
  std::optional<std::string> text = readFileText(path.string());
  return text && *text == content;
}

bool writeFile(const fs::path& path, std::string_view content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.flush();
  return static_cast<bool>(out);
}

std::string withSlash(const std::string& set) {
  return set.empty() || set.back() == '/' ? set : set + "/";
}

}  // namespace

std::optional<fs::path> templateCacheDir() {
  fs::path base;
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  if (xdg && *xdg && fs::path(xdg).is_absolute()) {
    base = xdg;
  } else if (home && *home) {
    base = fs::path(home) / ".cache";
  } else {
    return std::nullopt;
  }
  return base / "smachac" / std::string(kVersion) / "templates";
}

bool writeReadOnlyCopy(const fs::path& path, std::string_view content) {
  if (holds(path, content)) return true;
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (ec) return false;
  fs::path temporary = path;
  temporary += ".tmp" + std::to_string(getpid());
  fs::remove(temporary, ec);
  bool written = writeFile(temporary, content);
  if (written) {
    fs::permissions(temporary,
                    fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read, ec);
    fs::rename(temporary, path, ec);
  }
  if (!written || ec) fs::remove(temporary, ec);
  return written && !ec;
}

TemplateFinder::TemplateFinder(const Settings& settings)
    : path_(backends::targetTemplatePath(settings.target, settings.template_dirs)),
      env_(backends::targetEnvironment(settings.target, path_, converter_)) {}

std::optional<fs::path> TemplateFinder::file(std::string_view name) {
  std::optional<std::string> resolved = env_->resolveScriptTemplate(name);
  if (!resolved) return std::nullopt;
  for (const std::string& dir : path_.dirs) {
    std::error_code ec;
    fs::path candidate = fs::path(dir) / *resolved;
    if (fs::is_regular_file(candidate, ec)) return fs::absolute(candidate, ec).lexically_normal();
  }
  std::optional<fs::path> cache = templateCacheDir();
  for (const std::string& set : path_.builtin_sets) {
    std::string embedded = withSlash(set) + *resolved;
    for (const EmbeddedFile& builtin : path_.builtins) {
      if (builtin.path != embedded) continue;
      if (!cache) return std::nullopt;
      fs::path copy = (*cache / embedded).lexically_normal();
      return writeReadOnlyCopy(copy, builtin.content) ? std::optional(copy) : std::nullopt;
    }
  }
  return std::nullopt;
}

std::optional<std::string> TemplateFinder::documentation(std::string_view name) {
  std::optional<std::string> resolved = env_->resolveScriptTemplate(name);
  if (!resolved) return std::nullopt;
  try {
    return backends::templateHelpMarkdown(backends::templateMeta(*env_, *resolved));
  } catch (const std::exception&) {
    return std::nullopt;  // a broken meta block is reported when the template is rendered
  }
}

std::vector<std::string> TemplateFinder::outcomes(std::string_view name) {
  std::optional<std::string> resolved = env_->resolveScriptTemplate(name);
  if (!resolved) return {};
  try {
    std::optional<std::string> text = env_->metaBlock(*resolved);
    std::optional<backends::TemplateMeta> meta =
        text ? backends::parseTemplateMeta(*text) : std::nullopt;
    return meta ? meta->outcomes : std::vector<std::string>{};
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace smachac::lsp
