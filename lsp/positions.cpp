// UTF-8 bytes ↔ UTF-16 code units, per line.
#include "lsp/positions.h"

#include <algorithm>

namespace smachac::lsp {
namespace {

/// The length of the UTF-8 sequence that starts with `lead` (1 for a stray byte).
size_t sequenceLength(unsigned char lead) {
  if (lead >= 0xF0) return 4;
  if (lead >= 0xE0) return 3;
  if (lead >= 0xC0) return 2;
  return 1;
}

/// UTF-16 units in `bytes` (a four-byte sequence is a surrogate pair).
uint32_t utf16Length(std::string_view bytes) {
  uint32_t units = 0;
  for (size_t i = 0; i < bytes.size(); i += sequenceLength(bytes[i])) {
    units += sequenceLength(bytes[i]) == 4 ? 2 : 1;
  }
  return units;
}

/// The byte offset in `line` after `units` UTF-16 units (clamped to the line).
size_t byteOffset(std::string_view line, uint32_t units) {
  size_t i = 0;
  uint32_t seen = 0;
  while (i < line.size() && seen < units) {
    size_t length = sequenceLength(line[i]);
    seen += length == 4 ? 2 : 1;
    i = std::min(line.size(), i + length);
  }
  return i;
}

}  // namespace

LineIndex::LineIndex(std::string_view text) : text_(text) {
  starts_.push_back(0);
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') starts_.push_back(i + 1);
  }
}

std::string_view LineIndex::lineText(uint32_t line) const {
  if (line >= starts_.size()) return {};
  size_t begin = starts_[line];
  size_t end = line + 1 < starts_.size() ? starts_[line + 1] - 1 : text_.size();
  if (end > begin && text_[end - 1] == '\r') --end;
  return text_.substr(begin, end - begin);
}

size_t LineIndex::offsetOf(Position position) const {
  if (position.line >= starts_.size()) return text_.size();
  return starts_[position.line] + byteOffset(lineText(position.line), position.character);
}

Position LineIndex::positionOf(size_t offset) const {
  offset = std::min(offset, text_.size());
  auto after = std::upper_bound(starts_.begin(), starts_.end(), offset);
  auto line = static_cast<uint32_t>(after - starts_.begin() - 1);
  std::string_view text = lineText(line);
  size_t column = std::min(offset - starts_[line], text.size());
  return {line, utf16Length(text.substr(0, column))};
}

size_t LineIndex::offsetOf(const SourceLoc& loc) const {
  if (!loc.hasLine() || loc.line > starts_.size()) return 0;
  std::string_view text = lineText(loc.line - 1);
  return starts_[loc.line - 1] + std::min<size_t>(loc.column > 0 ? loc.column - 1 : 0, text.size());
}

Range LineIndex::rangeOf(const SourceLoc& loc) const {
  if (!loc.hasLine() || loc.line > starts_.size()) return {};
  size_t start = offsetOf(loc);
  size_t line_end = starts_[loc.line - 1] + lineText(loc.line - 1).size();
  size_t end = std::min(start + loc.length, line_end);
  return {positionOf(start), positionOf(end)};
}

Position positionFromJson(const Json& json) {
  return {json.at("line").get<uint32_t>(), json.at("character").get<uint32_t>()};
}

Json toJson(Position position) {
  return {{"line", position.line}, {"character", position.character}};
}

Json toJson(const Range& range) {
  return {{"start", toJson(range.start)}, {"end", toJson(range.end)}};
}

}  // namespace smachac::lsp
