// What a template's meta block declares about its variables (SMACHA's format):
// `variables` entries are `{var: {type, description}}` (required),
// `[{var: {...}}]` (optional), `[{a: ...}, {b: ...}]` (alternatives: one of them required) or
// `{heading: [entries...]}` (a group).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace smachac::backends {

struct TemplateVariable {
  std::string name;
  std::vector<std::string> types;  ///< as written: "str", "list of str", "float", ...
  bool required = false;
  int alternative_group = -1;  ///< >= 0: one variable of this group is required
};

struct TemplateMeta {
  std::vector<TemplateVariable> variables;
  std::vector<std::string> outcomes;  ///< the `outcomes` the template's states have
};

/// Parses the text of a meta block; nullopt when it is not YAML of the expected shape.
std::optional<TemplateMeta> parseTemplateMeta(std::string_view text);

}  // namespace smachac::backends
