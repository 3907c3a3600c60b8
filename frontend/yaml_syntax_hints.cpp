// Hints for yaml-cpp's syntax errors.
#include "frontend/yaml_syntax_hints.h"

namespace smachac::frontend {
namespace {

struct Hint {
  std::string_view message;  ///< yaml-cpp's, as it begins
  YamlSyntaxHint hint;       ///< its text is in the diagnostic registry
};

constexpr Hint kHints[] = {
    {"end of map not found", YamlSyntaxHint::IndentLikeSiblings},
    {"end of sequence flow not found", YamlSyntaxHint::CloseList},
    {"end of map flow not found", YamlSyntaxHint::CloseMapping},
    {"illegal map value", YamlSyntaxHint::KeyTooDeep},
    {"illegal block entry", YamlSyntaxHint::EntryOnOwnLine},
};

}  // namespace

std::optional<YamlSyntaxHint> yamlSyntaxHint(std::string_view message) {
  for (const Hint& h : kHints) {
    if (message.starts_with(h.message)) return h.hint;
  }
  return std::nullopt;
}

}  // namespace smachac::frontend
