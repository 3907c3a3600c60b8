// UTF-8 validation of script text (YAML requires it; NUL is never allowed).
#pragma once

#include <optional>
#include <string_view>

namespace smachac::frontend {

/// Offset of the first NUL byte or invalid UTF-8 sequence (overlong, surrogate, > U+10FFFF,
/// truncated), or nullopt when `text` is clean.
std::optional<size_t> findInvalidUtf8(std::string_view text);

}  // namespace smachac::frontend
