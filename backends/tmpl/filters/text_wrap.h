// Python's textwrap.wrap() as Jinja2's `wordwrap` filter uses it (no tab expansion, whitespace
// kept, hyphen-aware splitting) and JSON serialisation as Jinja2's `tojson` filter does it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "backends/tmpl/values/value.h"

namespace smachac::tmpl {

std::vector<std::string> wrapText(std::string_view text, int64_t width, bool break_long_words,
                                  bool break_on_hyphens);

/// json.dumps(value, sort_keys=True, indent=indent) with HTML-unsafe characters escaped.
std::string toJson(const Value& value, int64_t indent);

}  // namespace smachac::tmpl
