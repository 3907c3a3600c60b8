// The lexer: splits a template into data and tag tokens with Jinja2's whitespace rules
// (lstrip_blocks, `-`/`+` markers, raw blocks, comments) as SMACHA configures them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "backends/tmpl/lexer/token.h"

namespace smachac::tmpl {

struct LexerOptions {
  bool lstrip_blocks = true;
  bool trim_blocks = false;
};

/// Normalises newlines (\r\n and \r become \n) and drops one trailing newline, as Jinja2
/// does with keep_trailing_newline=False.
std::string normalizeSource(std::string_view source);

/// normalizeSource's result as a view of `source`, when there is no carriage return to replace;
/// nullopt otherwise.
std::optional<std::string_view> normalizedInPlace(std::string_view source);

/// Tokenises `source` (already normalised). Raises SyntaxFault on lexical errors.
std::vector<Token> tokenize(std::string_view source, const LexerOptions& options = {});

/// A syntax error at a byte offset of the source being lexed or parsed.
struct SyntaxFault {
  uint32_t pos;
  std::string message;
};

}  // namespace smachac::tmpl
