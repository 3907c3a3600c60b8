// Internal text helpers shared by the runtime's sources: names in messages, escaping for JSON
// and Python literals, and finding a name in a key list.
#pragma once

#include <string>
#include <string_view>

#include "smachac/runtime/userdata.h"

namespace smachac::runtime {

/// `name` in backticks, as every message writes names.
std::string backticked(std::string_view name);

enum class Escape { Json, Python };
/// Appends `text` between `quote`s, escaping backslashes, the quote and control characters
/// (\uXXXX for JSON, \xXX for Python).
void appendQuoted(std::string& out, std::string_view text, char quote, Escape style);

/// The position of `key` in `keys`, or -1.
int indexIn(const Keys& keys, std::string_view key);

}  // namespace smachac::runtime
