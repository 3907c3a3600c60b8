// Spans of YAML nodes, read from the text around their loader locations.
#include "refactor/yaml_spans.h"

#include "ir/support/check.h"

namespace smachac::refactor {
namespace {

bool isSpaceOrBreak(char c) { return isBlank(c) || c == '\n'; }

/// The offset after a quoted scalar that starts at `begin`.
size_t quotedEnd(std::string_view t, size_t begin) {
  char quote = t[begin];
  for (size_t i = begin + 1; i < t.size(); ++i) {
    if (quote == '"' && t[i] == '\\') {
      ++i;
    } else if (t[i] == quote) {
      if (quote == '\'' && i + 1 < t.size() && t[i + 1] == '\'') {
        ++i;
        continue;
      }
      return i + 1;
    }
  }
  return t.size();
}

size_t skipComment(std::string_view t, size_t i) {
  while (i < t.size() && t[i] != '\n') ++i;
  return i;
}

/// The offset after the flow collection that opens at `begin`.
size_t matchBracket(std::string_view t, size_t begin) {
  int depth = 0;
  bool scalar_start = true;
  for (size_t i = begin; i < t.size(); ++i) {
    char c = t[i];
    if ((c == '\'' || c == '"') && scalar_start) {
      i = quotedEnd(t, i) - 1;
      scalar_start = false;
    } else if (c == '#' && (i == 0 || isSpaceOrBreak(t[i - 1]))) {
      i = skipComment(t, i) - 1;
    } else if (c == '[' || c == '{') {
      ++depth;
      scalar_start = true;
    } else if (c == ']' || c == '}') {
      if (--depth == 0) return i + 1;
      scalar_start = false;
    } else if (c == ',' || c == ':' || c == '?') {
      scalar_start = true;
    } else if (!isSpaceOrBreak(c)) {
      scalar_start = false;
    }
  }
  return t.size();
}

size_t trimBack(std::string_view t, size_t begin, size_t end) {
  while (end > begin && isSpaceOrBreak(t[end - 1])) --end;
  return end;
}

/// The end of a plain scalar inside a flow collection.
size_t flowPlainEnd(std::string_view t, size_t begin) {
  size_t i = begin;
  for (; i < t.size(); ++i) {
    char c = t[i];
    if (c == ',' || c == ']' || c == '}') break;
    if (c == '#' && i > begin && isSpaceOrBreak(t[i - 1])) break;
  }
  return trimBack(t, begin, i);
}

/// The end of a line's text without a trailing comment and blanks, from `begin` on it.
size_t lineContentEnd(const SourceText& text, size_t begin) {
  std::string_view t = text.text();
  size_t end = text.lineEnd(text.lineOf(begin));
  for (size_t i = begin; i < end; ++i) {
    if (t[i] == '#' && i > begin && isBlank(t[i - 1])) {
      end = i;
      break;
    }
  }
  return trimBack(t, begin, end);
}

/// The last line of a block node that starts on line `first`.
size_t blockLastLine(const SourceText& text, size_t first, Context context) {
  size_t last = first;
  for (size_t line = first + 1; line < text.lineCount(); ++line) {
    bool content = text.isContentLine(line);
    if (!content && !text.isCommentLine(line)) continue;  // blank
    size_t indent = text.indentOf(line);
    if (indent > context.owner) {
      last = line;
      continue;
    }
    size_t at = text.lineStart(line) + indent;
    bool dash = text.at(at) == '-' && isSpaceOrBreak(text.at(at + 1));
    if (content && context.under_key && indent == context.owner && dash) {
      last = line;
      continue;
    }
    if (content) break;
  }
  return last;
}

size_t keyTokenEnd(const SourceText& text, const ir::MapEntry& entry) {
  std::string_view t = text.text();
  size_t begin = text.offsetOf(entry.key_loc);
  if (t[begin] == '\'' || t[begin] == '"') return quotedEnd(t, begin);
  size_t i = begin;
  while (i < t.size() &&
         !(t[i] == ':' && (i + 1 >= t.size() || isSpaceOrBreak(t[i + 1]) || t[i + 1] == ',' ||
                           t[i + 1] == '}' || t[i + 1] == ']'))) {
    if (t[i] == '\n') break;
    ++i;
  }
  return trimBack(t, begin, i);
}

bool isEmptyValue(const ir::MapEntry& entry) {
  return entry.value.isNull() && entry.value.loc == entry.key_loc;
}

}  // namespace

size_t nodeStart(const SourceText& text, const ir::Value& node) {
  std::string_view t = text.text();
  size_t i = text.offsetOf(node.loc);
  while (i < t.size() && (t[i] == '!' || t[i] == '&')) {
    while (i < t.size() && !isSpaceOrBreak(t[i])) ++i;
    while (i < t.size() && isSpaceOrBreak(t[i])) ++i;
  }
  return i;
}

bool isFlowCollection(const SourceText& text, const ir::Value& node) {
  if (!node.isMap() && !node.isList()) return false;
  char c = text.at(nodeStart(text, node));
  return c == '{' || c == '[';
}

Span nodeSpan(const SourceText& text, const ir::Value& node, Context context) {
  std::string_view t = text.text();
  size_t begin = nodeStart(text, node);
  char c = text.at(begin);
  if ((node.isMap() || node.isList()) && (c == '{' || c == '[')) {
    return {begin, matchBracket(t, begin)};
  }
  if ((c == '\'' || c == '"') && !node.isMap() && !node.isList()) {
    return {begin, quotedEnd(t, begin)};
  }
  if (context.flow) return {begin, flowPlainEnd(t, begin)};
  size_t first = text.lineOf(begin);
  size_t last = blockLastLine(text, first, context);
  bool collection = node.isMap() || node.isList() || c == '|' || c == '>';
  if (collection) return {begin, text.lineEnd(last)};
  return {begin, lineContentEnd(text, last == first ? begin : text.lineStart(last))};
}

Context entryContext(const SourceText& text, const ir::Value& map, const ir::MapEntry& entry) {
  if (isFlowCollection(text, map)) return {true, 0, false};
  return {false, text.columnOf(text.offsetOf(entry.key_loc)), true};
}

Context itemContext(const SourceText& text, const ir::Value& list) {
  if (isFlowCollection(text, list)) return {true, 0, false};
  return {false, text.columnOf(nodeStart(text, list)), false};
}

Span keySpan(const SourceText& text, const ir::MapEntry& entry) {
  return {text.offsetOf(entry.key_loc), keyTokenEnd(text, entry)};
}

Span entryValueSpan(const SourceText& text, const ir::Value& map, const ir::MapEntry& entry) {
  if (!isEmptyValue(entry)) return nodeSpan(text, entry.value, entryContext(text, map, entry));
  size_t colon = keyTokenEnd(text, entry);
  while (colon < text.size() && text.at(colon) != ':') ++colon;
  size_t after = std::min(colon + 1, text.size());
  return {after, after};
}

Span entrySpan(const SourceText& text, const ir::Value& map, const ir::MapEntry& entry) {
  return {text.offsetOf(entry.key_loc), entryValueSpan(text, map, entry).end};
}

Span entryLines(const SourceText& text, const ir::Value& map, const ir::MapEntry& entry) {
  SMACHAC_CHECK(!isFlowCollection(text, map), "entryLines needs a block mapping");
  Span span = entrySpan(text, map, entry);
  size_t first = text.lineOf(span.begin);
  size_t floor = 0;  // the first line after the previous entry
  const ir::Map& entries = map.asMap();
  for (size_t i = 1; i < entries.size(); ++i) {
    if (&entries[i] == &entry) floor = lastLineOf(text, entrySpan(text, map, entries[i - 1])) + 1;
  }
  while (first > floor && text.isCommentLine(first - 1)) --first;
  return {text.lineStart(first), text.nextLineStart(lastLineOf(text, span))};
}

Span listItemSpan(const SourceText& text, const ir::Value& list, const ir::Value& item) {
  Context context = itemContext(text, list);
  if (context.flow && item.isMap() && !isFlowCollection(text, item) && !item.asMap().empty()) {
    return {nodeStart(text, item), entrySpan(text, item, item.asMap().back()).end};
  }
  return nodeSpan(text, item, context);
}

size_t lastLineOf(const SourceText& text, Span span) {
  return text.lineOf(span.end > span.begin ? span.end - 1 : span.begin);
}

}  // namespace smachac::refactor
