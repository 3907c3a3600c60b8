// New YAML text in flow style, as SMACHA writes small maps and lists (`{a: 1, b: [x, y]}`).
// Rules:
//   * a string is plain when YAML reads it back as the same string (not null, a bool or a
//     number, no indicator first, no `: `, ` #`, flow indicators or line breaks); otherwise
//     single-quoted, or double-quoted with escapes when it holds line breaks or controls
//   * an expression is its backtick text, quoted; a `!str` string keeps its tag
//   * floats print as Python's repr (`.inf`, `-.inf`, `.nan` for the special values)
//   * a value copied from the script keeps its own text when that text is one line
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ir/value.h"
#include "refactor/text_edits.h"

namespace smachac::refactor {

std::string flowScalar(std::string_view text);
std::string flowValue(const ir::Value& value);

/// `[a, b]` of names.
std::string flowNameList(const std::vector<std::string>& names);

/// `{k: v, ...}`: keys through flowScalar, values already YAML text.
std::string flowMap(const std::vector<std::pair<std::string, std::string>>& entries);

/// A value of the script as one line of flow YAML: its text with `edits` applied when the
/// span is on one line, else flowValue(value).
std::string inlineText(const SourceText& text, const EditList& edits, const ir::Value& value,
                       Span span);

}  // namespace smachac::refactor
