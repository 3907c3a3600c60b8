// What can be known of a template from its source without rendering it, so that the generator
// can skip work whose result is known: a block whose isolated render is always empty, and the
// module pass of a template that cannot export anything. SMACHA renders every block of every
// state (13 per state) and runs a module pass per state; for the built-in state templates most
// of those renders are empty.
//
// The analysis is conservative and only covers "simple" templates, where the engine's result
// is certain: outside blocks only whitespace, comments, `extends` (a string literal), `from`/
// `import`, `set` and `macro` definitions; no nested blocks, no `raw`. For such a chain of
// templates (the template and what it extends), a block renders empty in isolation when the
// root of the chain has no such block in its layout, or when the block's most derived
// definition holds only whitespace and comments. A template that is not simple, or whose source
// cannot be found the way the engine finds it, gets no shape, and everything is rendered.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "backends/generator/template_catalog.h"

namespace smachac::generator {

struct TemplateShape {
  bool may_export = true;             ///< some template of the chain has a `set` or a `macro`
  std::set<std::string> layout;       ///< the blocks of the chain's root template
  std::map<std::string, bool> blank;  ///< block → its most derived definition is blank

  /// Whether rendering `block` in isolation always gives "".
  bool rendersEmpty(const std::string& block) const;
};

/// One template file's outline, from its source text.
struct TemplateOutline {
  bool simple = false;
  std::optional<std::string> parent;  ///< the template it extends
  bool has_set_or_macro = false;
  std::map<std::string, bool> blocks;  ///< block name → its body is blank
};

/// Outlines a template source (see the header comment for what "simple" means).
TemplateOutline outlineTemplate(std::string_view source);

class TemplateShapes {
 public:
  explicit TemplateShapes(const TemplatePath& path) : path_(path) {}

  /// The shape of template `name` (an exact name), or nullopt when unknown.
  const std::optional<TemplateShape>& shape(const std::string& name);

 private:
  std::optional<TemplateShape> analyze(const std::string& name);
  /// The outlines of `name` and of what it extends, most derived first; nullopt when some
  /// template of the chain is not simple or not found.
  std::optional<std::vector<TemplateOutline>> chain(const std::string& name);

  TemplatePath path_;
  std::map<std::string, std::optional<TemplateShape>, std::less<>> shapes_;
};

}  // namespace smachac::generator
