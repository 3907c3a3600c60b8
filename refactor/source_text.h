// The text of a script as lines: byte offsets of loader locations (1-based line and column,
// columns in bytes as yaml-cpp counts them), line boundaries and indentation. Rules:
//   * a line ends before its '\n'; a trailing '\r' belongs to the line's text
//   * a content line has something other than spaces, tabs, '\r' and a comment
//   * indentation counts leading spaces only (YAML forbids tabs there)
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "ir/support/source_loc.h"

namespace smachac::refactor {

/// A byte range [begin, end) of the source.
struct Span {
  size_t begin = 0;
  size_t end = 0;
};

class SourceText {
 public:
  explicit SourceText(std::string text);

  std::string_view text() const { return text_; }
  size_t size() const { return text_.size(); }
  char at(size_t offset) const { return offset < text_.size() ? text_[offset] : '\0'; }

  /// The offset of a loader location in this text.
  size_t offsetOf(SourceLoc loc) const;
  /// The 0-based column of an offset.
  size_t columnOf(size_t offset) const { return offset - lineStart(lineOf(offset)); }

  size_t lineCount() const { return starts_.size(); }
  /// The 0-based line holding `offset`.
  size_t lineOf(size_t offset) const;
  size_t lineStart(size_t line) const { return starts_[line]; }
  /// The end of the line's text (its '\n', or the end of the file).
  size_t lineEnd(size_t line) const;
  /// The start of the next line (after the '\n'), or the end of the file.
  size_t nextLineStart(size_t line) const;
  size_t indentOf(size_t line) const;
  bool isContentLine(size_t line) const;
  bool isCommentLine(size_t line) const;

 private:
  std::string text_;
  std::vector<size_t> starts_;
};

/// Spaces, tabs and '\r'.
inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

}  // namespace smachac::refactor
