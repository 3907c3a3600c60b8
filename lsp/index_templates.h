// The templates a document's states name, found as the target of the settings finds them
// (the -I directories in order, then its built-in sets): the file that defines one and the
// documentation of its meta block.
//
// A built-in template lives in the binary; its file is a copy written once to the cache,
// `$XDG_CACHE_HOME/smachac/<version>/templates/<set>/<file>` (else `$HOME/.cache/...`):
// written atomically (a temporary file renamed over), read-only (0444), the same bytes for
// the same version; an existing copy with other bytes is replaced.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "backends/generator/template_catalog.h"
#include "backends/generator/template_values.h"
#include "backends/tmpl/environment.h"
#include "lsp/settings.h"

namespace smachac::lsp {

class TemplateFinder {
 public:
  explicit TemplateFinder(const Settings& settings);

  /// The path of the file template `name` is read from (a built-in one's cache copy);
  /// nullopt when there is no such template or its copy cannot be written.
  std::optional<std::filesystem::path> file(std::string_view name);
  /// The template's documentation in markdown (backends/meta/template_help.h); nullopt when there
  /// is no such template or it has no meta block that parses.
  std::optional<std::string> documentation(std::string_view name);
  /// The outcomes its meta block lists (empty when unknown).
  std::vector<std::string> outcomes(std::string_view name);

 private:
  generator::TemplatePath path_;
  generator::ValueConverter converter_;
  std::unique_ptr<tmpl::Environment> env_;
};

/// Where built-in templates are copied; nullopt when neither XDG_CACHE_HOME nor HOME is set.
std::optional<std::filesystem::path> templateCacheDir();

/// Makes `path` a read-only file holding `content` (see above); false when it cannot.
bool writeReadOnlyCopy(const std::filesystem::path& path, std::string_view content);

}  // namespace smachac::lsp
