// Line table of a script's text.
#include "refactor/source_text.h"

#include <algorithm>

namespace smachac::refactor {

SourceText::SourceText(std::string text) : text_(std::move(text)) {
  starts_.push_back(0);
  for (size_t i = 0; i < text_.size(); ++i) {
    if (text_[i] == '\n') starts_.push_back(i + 1);
  }
}

size_t SourceText::offsetOf(SourceLoc loc) const {
  if (loc.line == 0 || loc.line > starts_.size()) return text_.size();
  size_t line = loc.line - 1;
  size_t column = loc.column == 0 ? 0 : loc.column - 1;
  return std::min(starts_[line] + column, lineEnd(line));
}

size_t SourceText::lineOf(size_t offset) const {
  auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
  return static_cast<size_t>(it - starts_.begin()) - 1;
}

size_t SourceText::lineEnd(size_t line) const {
  return line + 1 < starts_.size() ? starts_[line + 1] - 1 : text_.size();
}

size_t SourceText::nextLineStart(size_t line) const {
  return line + 1 < starts_.size() ? starts_[line + 1] : text_.size();
}

size_t SourceText::indentOf(size_t line) const {
  size_t i = starts_[line];
  size_t end = lineEnd(line);
  while (i < end && text_[i] == ' ') ++i;
  return i - starts_[line];
}

bool SourceText::isContentLine(size_t line) const {
  for (size_t i = starts_[line], end = lineEnd(line); i < end; ++i) {
    if (isBlank(text_[i])) continue;
    return text_[i] != '#';
  }
  return false;
}

bool SourceText::isCommentLine(size_t line) const {
  for (size_t i = starts_[line], end = lineEnd(line); i < end; ++i) {
    if (isBlank(text_[i])) continue;
    return text_[i] == '#';
  }
  return false;
}

}  // namespace smachac::refactor
