// Printing values like Python: str() (what `{{ x }}` outputs) and repr() (inside containers),
// with floats in shortest round-trip form and strings quoted and escaped like Python's repr.
#pragma once

#include <string>
#include <string_view>

#include "backends/tmpl/values/value.h"

namespace smachac::tmpl {

void appendStr(std::string& out, const Value& v);
void appendRepr(std::string& out, const Value& v);
/// Python's repr() of a str (appendPythonStringRepr, with a fast path for plain ASCII).
void appendStringRepr(std::string& out, std::string_view text);
std::string str(const Value& v);
std::string repr(const Value& v);

void appendFloatRepr(std::string& out, double d);
void appendInt(std::string& out, int64_t i);

/// HTML escaping of & < > ' " (MarkupSafe's escape).
std::string htmlEscape(std::string_view s);

}  // namespace smachac::tmpl
