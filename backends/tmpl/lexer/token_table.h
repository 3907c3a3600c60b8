// Token streams stored as data: the build lexes the built-in templates once and embeds their
// tokens (tools/cmake/embed_gen.cpp), so that a compile does not lex them again. Two 32-bit
// words a token: `kind | length << 8`, then its byte offset in the normalised source. Rules:
// unpacking checks every token against the source it is given (kinds, bounds, order, the
// closing end-of-template token); words that do not fit it are refused and the source is
// lexed instead.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "backends/tmpl/lexer/token.h"

namespace smachac::tmpl {

/// The words of `tokens` (of a source shorter than 4 GiB, tokens shorter than 16 MiB).
std::vector<uint32_t> packTokens(const std::vector<Token>& tokens);

/// The tokens of `words` (positions in `source`); nullopt if they do not fit it.
std::optional<std::vector<Token>> unpackTokens(std::span<const uint32_t> words,
                                               std::string_view source);

}  // namespace smachac::tmpl
