// Positions as the protocol counts them (0-based line, UTF-16 code units in the line) and as
// the compiler does (byte offsets; SourceLoc's 1-based line and byte column).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "ir/support/source_loc.h"
#include "lsp/json_rpc.h"

namespace smachac::lsp {

struct Position {
  uint32_t line = 0;
  uint32_t character = 0;  ///< UTF-16 code units
  friend auto operator<=>(const Position&, const Position&) = default;
};

struct Range {
  Position start;
  Position end;
  friend bool operator==(const Range&, const Range&) = default;
};

/// The line starts of one text; the text must outlive the index.
class LineIndex {
 public:
  explicit LineIndex(std::string_view text);

  /// The byte offset of a position, clamped to its line (and to the text).
  size_t offsetOf(Position position) const;
  Position positionOf(size_t offset) const;
  /// The range of a SourceLoc in this text (line 0, the whole file: the empty range at 0:0).
  Range rangeOf(const SourceLoc& loc) const;
  /// The byte offset of a SourceLoc's start.
  size_t offsetOf(const SourceLoc& loc) const;
  uint32_t lineCount() const { return static_cast<uint32_t>(starts_.size()); }
  std::string_view lineText(uint32_t line) const;

 private:
  std::string_view text_;
  std::vector<size_t> starts_;
};

Position positionFromJson(const Json& json);
Json toJson(Position position);
Json toJson(const Range& range);

}  // namespace smachac::lsp
