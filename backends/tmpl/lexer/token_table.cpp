// Packing and checked unpacking of token streams (see token_table.h).
#include "backends/tmpl/lexer/token_table.h"

namespace smachac::tmpl {
namespace {

constexpr uint32_t kKindBits = 8;
constexpr uint32_t kKindMask = (1u << kKindBits) - 1;

}  // namespace

std::vector<uint32_t> packTokens(const std::vector<Token>& tokens) {
  std::vector<uint32_t> words;
  words.reserve(tokens.size() * 2);
  for (const Token& token : tokens) {
    words.push_back(static_cast<uint32_t>(token.kind) | token.length << kKindBits);
    words.push_back(token.pos);
  }
  return words;
}

std::optional<std::vector<Token>> unpackTokens(std::span<const uint32_t> words,
                                               std::string_view source) {
  if (words.size() < 2 || words.size() % 2 != 0) return std::nullopt;
  std::vector<Token> tokens(words.size() / 2);
  uint32_t last_pos = 0;
  for (size_t i = 0; i < tokens.size(); ++i) {
    uint32_t kind = words[2 * i] & kKindMask;
    uint32_t length = words[2 * i] >> kKindBits;
    uint32_t pos = words[2 * i + 1];
    if (kind > static_cast<uint32_t>(Tok::Eof) || pos < last_pos || pos > source.size() ||
        length > source.size() - pos) {
      return std::nullopt;
    }
    tokens[i] = Token{static_cast<Tok>(kind), pos, length};
    last_pos = pos;
  }
  const Token& end = tokens.back();
  if (!end.is(Tok::Eof) || end.pos != source.size()) return std::nullopt;
  return tokens;
}

}  // namespace smachac::tmpl
