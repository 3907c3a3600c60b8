// `!expr` scalars: the text of a portable expression parsed where it stands in the script, so
// that each node and each syntax error points at its own column. yaml-cpp reports a tagged
// scalar at its tag; the scalar's text is found after the tag in the document (behind its
// quote, if quoted). When the text in the document is not the scalar's value as is (escapes,
// folded lines), every location falls back to the tag.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "ir/support/source_loc.h"
#include "ir/value.h"

namespace smachac::frontend {

inline constexpr std::string_view kPortableExprTag = "!expr";

/// A located syntax error of an `!expr` scalar.
struct ExprScalarError {
  SourceLoc loc;
  std::string message;
};

class ExprScalarReader {
 public:
  ExprScalarReader(uint32_t file, std::string_view document) : file_(file), document_(document) {}

  /// The portable expression of the scalar `value` tagged at 0-based (line, column), or the
  /// error that stops its parse (`error` set, the value null).
  ir::Value read(int line, int column, std::string_view value,
                 std::optional<ExprScalarError>& error);

 private:
  /// Byte offset of a 0-based (line, column); lines are found forward from the last call.
  size_t offsetOf(int line, int column);
  /// Offset of the scalar's text after its tag, or npos when it is not `value` as written.
  size_t textOffset(size_t tag_offset, std::string_view value) const;

  uint32_t file_;
  std::string_view document_;
  int cached_line_ = 0;
  size_t cached_offset_ = 0;
};

}  // namespace smachac::frontend
