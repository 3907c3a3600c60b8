// Hints for yaml-cpp's syntax errors.
#include "frontend/yaml_syntax_hints.h"

namespace smachac::frontend {
namespace {

struct Hint {
  std::string_view message;  ///< yaml-cpp's, as it begins
  std::string_view hint;
};

constexpr Hint kHints[] = {
    {"end of map not found",
     "this line is indented like no key above it: indent it as its sibling keys are, or "
     "start a new list entry (a state) with `- `"},
    {"end of sequence flow not found",
     "a `[` list is not closed: add its `]`, also when the list spans several lines"},
    {"end of map flow not found",
     "a `{` mapping is not closed: add its `}`, also when the mapping spans several lines"},
    {"illegal map value",
     "a `key:` here is not at the indentation of a mapping: the line is indented deeper than "
     "the key above it, or a `- ` is missing before it"},
    {"illegal block entry",
     "a `- ` list entry must begin a line of its own, indented under its key"},
};

}  // namespace

std::optional<std::string> yamlSyntaxHint(std::string_view message) {
  for (const Hint& h : kHints) {
    if (message.starts_with(h.message)) return std::string(h.hint);
  }
  return std::nullopt;
}

}  // namespace smachac::frontend
