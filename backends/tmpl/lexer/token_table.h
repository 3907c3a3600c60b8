// Token streams stored as data: the build lexes the built-in templates once and embeds their
// tokens (tools/cmake/embed_gen.cpp), so that a compile does not lex them again. Three 32-bit
// words a token, the layout of `Token` on a little-endian machine: the kind (its byte, then
// zeros), the byte offset in the normalised source, the length. The engine reads the stored
// words in place as tokens, without copying them. Rules: the words are checked against the
// source they are given before use (kinds, bounds, order, the closing end-of-template token);
// words that do not fit it, or a machine whose layout differs, are refused and the source is
// lexed instead.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "backends/tmpl/lexer/token.h"

namespace smachac::tmpl {

/// The words of `tokens` (of a source shorter than 4 GiB).
std::vector<uint32_t> packTokens(const std::vector<Token>& tokens);

/// The tokens `words` hold (positions in `source`), viewed in place; nullopt if they do not
/// fit it.
std::optional<std::span<const Token>> storedTokens(std::span<const uint32_t> words,
                                                   std::string_view source);

}  // namespace smachac::tmpl
