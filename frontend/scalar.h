// YAML 1.2 core-schema resolution of scalars, as ruamel.yaml (SMACHA's loader) does it:
//   plain `~ null Null NULL` and empty → null; `true True TRUE false False FALSE` → bool
//   (`yes`/`no`/`on`/`off` stay strings); decimal, 0o octal and 0x hex → int; decimal floats,
//   `.inf`, `-.inf`, `.nan` → float; everything else, and every quoted scalar → string.
// A string in backticks is an expression. Tags `!str` and `!!str` force a string.
#pragma once

#include <optional>
#include <string_view>

#include "ir/value.h"

namespace smachac::frontend {

enum class ScalarStyle { Plain, Quoted };

struct ScalarResult {
  ir::Value value;
  bool int_overflow = false;  ///< an integer that does not fit in int64 (value holds 0)
};

/// A string value, or an expression when the text is in backticks (`code`).
ir::Value textValue(std::string_view text, SourceLoc loc);

ScalarResult resolveScalar(std::string_view text, ScalarStyle style, std::string_view tag,
                           SourceLoc loc);

}  // namespace smachac::frontend
