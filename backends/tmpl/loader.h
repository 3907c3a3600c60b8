// Finding template sources: in-memory templates, then the user's template directories in
// order, then the built-in sets of the embedded table. Exact names (`State.tpl.py`) and
// script-level names (`State` -> `State.tpl.py`, `State.tpl` or `State.tpl.<ext>`).
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/tmpl/template_files.h"
#include "ir/support/embedded_file.h"

namespace smachac::tmpl {

struct TemplateSource {
  std::string origin;             // what errors name: a file path or `<builtin>/smach/State.tpl.py`
  std::string read;               // the text of a file or an in-memory template
  bool builtin = false;           // from the embedded table (text that the build checked compiles)
  std::string_view builtin_text;  // a built-in template's text: a view of the table
  std::span<const uint32_t> tokens;  // the build's tokens of a built-in template, if any
  std::span<const uint8_t> image;    // the build's image of a built-in template, if any

  std::string_view text() const { return builtin ? builtin_text : std::string_view(read); }
};

class Loader {
 public:
  Loader(std::vector<std::string> dirs, std::vector<std::string> builtin_sets,
         std::span<const EmbeddedFile> builtins);

  /// The source of the template with exactly this name, searched in order. Raises Fault if a
  /// file exists but cannot be read.
  std::optional<TemplateSource> load(std::string_view name) const;
  bool exists(std::string_view name) const;
  /// Resolves a script-level name to a template name (see header comment).
  std::optional<std::string> resolveScriptName(std::string_view name) const;
  /// "`dir1`, `dir2`, built-in `smach/`": where templates are looked for.
  std::string searchDescription() const;
  void addMemory(std::string name, std::string text);

 private:
  std::optional<std::string> resolveIn(const std::vector<std::string_view>& entries,
                                       std::string_view name) const;
  const EmbeddedFile* findBuiltin(std::string_view path) const;

  std::vector<std::string> dirs_;
  std::vector<std::string> builtin_sets_;
  // Sorted by path; views into the caller's table, which outlives the loader (an
  // Environment's builtins). A sorted vector: one allocation for a table of a hundred.
  std::vector<EmbeddedFile> builtins_;
  std::map<std::string, std::string, std::less<>> memory_;
  mutable Listings listings_;  // of the directories searched, while they stay the same
};

/// Normalises a template name like Jinja2's split_template_path; nullopt if it escapes the
/// search directories (`..`) or is empty.
std::optional<std::string> normalizeTemplateName(std::string_view name);

}  // namespace smachac::tmpl
