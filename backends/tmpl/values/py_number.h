// Python's int() and float() parsing of strings (whitespace, signs, underscores between
// digits, base prefixes, inf/nan spellings).
#pragma once

#include <cstdint>
#include <string_view>

namespace smachac::tmpl {

/// Python float(s); false when Python would raise ValueError.
bool parsePythonFloat(std::string_view s, double& out);
/// Python int(s, base) for base 0 or 2..36; false when Python would raise ValueError or the
/// value does not fit in 64 bits (`overflow` set).
bool parsePythonInt(std::string_view s, int base, int64_t& out, bool& overflow);

}  // namespace smachac::tmpl
