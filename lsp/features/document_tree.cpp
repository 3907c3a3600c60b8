// The outline tree of a document, and where its nodes end.
#include "lsp/features/document_tree.h"

#include <algorithm>
#include <cstdint>

#include "frontend/shorthand.h"
#include "lsp/yaml_sketch.h"

namespace smachac::lsp {
namespace {

/// The indentation of the line that holds `offset`.
size_t indentOf(std::string_view text, size_t offset) {
  size_t line_start = text.rfind('\n', offset == 0 ? 0 : offset - 1);
  line_start = line_start == std::string_view::npos || offset == 0 ? 0 : line_start + 1;
  size_t first = text.find_first_not_of(" \t", line_start);
  return (first == std::string_view::npos ? text.size() : first) - line_start;
}

/// Whether the line after the newline at `newline` holds text indented no deeper than
/// `indent`: a flow collection open before it was left unclosed (as the sketch reads it).
bool endsFlow(std::string_view text, size_t newline, size_t indent) {
  size_t first = text.find_first_not_of(" \t", newline + 1);
  if (first == std::string_view::npos || text[first] == '\n' || text[first] == '#') return false;
  return first - (newline + 1) <= indent;
}

/// Just after the bracket that closes the flow collection opening at `open` (quotes and
/// comments skipped), or npos when it is not closed.
size_t closingBracket(std::string_view text, size_t open) {
  size_t indent = indentOf(text, open);
  size_t depth = 0;
  for (size_t i = open; i < text.size(); ++i) {
    char c = text[i];
    if (c == '\'' || c == '"') {
      i = std::min(text.find(c, i + 1), text.size());
    } else if (c == '#' && (text[i - 1] == ' ' || text[i - 1] == '\t')) {
      i = std::min(text.find('\n', i), text.size()) - 1;
    } else if (c == '\n' && endsFlow(text, i, indent)) {
      return std::string_view::npos;
    } else if (c == '{' || c == '[') {
      ++depth;
    } else if ((c == '}' || c == ']') && --depth == 0) {
      return i + 1;
    }
  }
  return std::string_view::npos;
}

/// The end of a scalar's span, kept on its line (a multi-line scalar ends with its first line).
size_t scalarEnd(const SourceLoc& loc, const LineIndex& lines) {
  size_t start = lines.offsetOf(loc);
  if (loc.line == 0) return start;
  size_t line_end = lines.offsetOf(Position{loc.line - 1, UINT32_MAX});
  return std::min<size_t>(start + loc.length, line_end);
}

}  // namespace

DocumentTree::DocumentTree(const Analysis& analysis) : analysis_(analysis) {
  if (!analysis.yaml) sketch_ = sketchYaml(analysis.text(), analysis.file);
}

size_t nodeEnd(const ir::Value& node, const LineIndex& lines, std::string_view text) {
  size_t start = lines.offsetOf(node.loc);
  bool collection = node.isMap() || node.isList();
  if (collection && start < text.size() && (text[start] == '{' || text[start] == '[')) {
    size_t close = closingBracket(text, start);
    if (close != std::string_view::npos) return close;
  }
  if (node.isMap() && !node.asMap().empty()) {
    const ir::MapEntry& last = node.asMap().back();
    size_t key_end = scalarEnd(last.key_loc, lines);
    return last.value.isNull() ? key_end : std::max(key_end, nodeEnd(last.value, lines, text));
  }
  if (node.isList() && !node.asList().empty()) return nodeEnd(node.asList().back(), lines, text);
  return scalarEnd(node.loc, lines);
}

const ir::MapEntry* findKey(const ir::Value& map, std::string_view key) {
  if (!map.isMap()) return nullptr;
  for (const ir::MapEntry& entry : map.asMap()) {
    if (frontend::longhandOf(entry.key).value_or(entry.key) == key) return &entry;
  }
  return nullptr;
}

}  // namespace smachac::lsp
