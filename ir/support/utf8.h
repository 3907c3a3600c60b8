// UTF-8 validation of script text (YAML requires it; NUL is never allowed).
#pragma once

#include <optional>
#include <string_view>

namespace smachac {

/// Offset of the first NUL byte or invalid UTF-8 sequence (overlong, surrogate, > U+10FFFF,
/// truncated), or nullopt when `text` is clean.
std::optional<size_t> findInvalidUtf8(std::string_view text);

/// Length of the valid UTF-8 sequence starting at byte `i` (1 to 4), or 0 when the bytes there
/// are no valid sequence or a NUL.
size_t utf8SequenceLength(std::string_view text, size_t i);

}  // namespace smachac
