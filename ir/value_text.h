// The text form of values in the IR printer: YAML-like flow style, strings double-quoted with
// C escapes, expressions in backticks, floats as Python prints them.
#pragma once

#include <string>
#include <string_view>

#include "ir/value.h"

namespace smachac::ir {

std::string formatValue(const Value& value);
/// A double-quoted, escaped string (control characters and non-UTF-8 bytes as \xNN).
std::string quoteString(std::string_view text);
/// `text` itself when it is a plain word ([A-Za-z0-9_.-/]+), else quoteString(text).
std::string formatKey(std::string_view text);

}  // namespace smachac::ir
