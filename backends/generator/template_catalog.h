// What templates a script can name, and where template errors point. The catalog lists the
// script-level names (`Foo` for `Foo.tpl.py`, `Foo.tpl`, `Foo.tpl.<ext>`) in the -I
// directories and the built-in sets, for "did you mean" suggestions. TemplateFiles registers
// the template files that diagnostics quote in the SourceManager, once each.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "backends/tmpl/error.h"
#include "ir/support/embedded_file.h"
#include "ir/support/source_loc.h"
#include "ir/support/source_manager.h"

namespace smachac::generator {

/// Where templates are searched: the user's directories, then built-in set prefixes
/// ("smach/") into the embedded table `builtins`.
struct TemplatePath {
  std::vector<std::string> dirs;
  std::vector<std::string> builtin_sets;
  std::span<const EmbeddedFile> builtins;
};

/// The sorted, de-duplicated script-level names of every template on the path (hidden files
/// and non-template files skipped).
std::vector<std::string> templateNames(const TemplatePath& path);

/// "`dir`, built-in `smach`": the path as diagnostics describe it.
std::string describePath(const TemplatePath& path);

/// The source of the template with exactly this name, found as the engine finds it (the
/// directories in order, then the built-in sets); nullopt when not found, or for a name with
/// `.`, `..` or empty path segments, which the engine normalises.
std::optional<std::string> readTemplateSource(const TemplatePath& path, std::string_view name);

/// The embedded path (e.g. "smach/Base.tpl.py") of the template with exactly this name when
/// the engine reads it from the built-in sets; nullopt when a directory's file comes first, or
/// it is not built in.
std::optional<std::string> builtinTemplatePath(const TemplatePath& path, std::string_view name);

/// The template name closest to `name` (ir/support/suggest.h), if one is close enough.
std::optional<std::string> closestTemplate(std::string_view name, const TemplatePath& path);

/// "; did you mean `X`?" for the closest template name, or "".
std::string suggestTemplate(std::string_view name, const TemplatePath& path);

class TemplateFiles {
 public:
  TemplateFiles(SourceManager& sources, std::span<const EmbeddedFile> builtins)
      : sources_(sources), builtins_(builtins) {}

  /// The location a template error names; the template's text is registered so that the
  /// diagnostic can quote its line.
  SourceLoc locate(const tmpl::TemplateError& error);

 private:
  std::optional<std::string> text(const std::string& origin) const;

  SourceManager& sources_;
  std::span<const EmbeddedFile> builtins_;
  std::map<std::string, uint32_t, std::less<>> files_;
};

}  // namespace smachac::generator
