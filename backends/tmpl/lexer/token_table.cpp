// Packing and checked in-place reading of token streams (see token_table.h).
#include "backends/tmpl/lexer/token_table.h"

#include <bit>
#include <cstddef>

namespace smachac::tmpl {
namespace {

constexpr size_t kWordsPerToken = 3;

/// Whether the words of a token are the bytes of a `Token` on this machine.
constexpr bool kLayoutFits = std::endian::native == std::endian::little &&
                             sizeof(Token) == kWordsPerToken * sizeof(uint32_t) &&
                             offsetof(Token, kind) == 0 && offsetof(Token, pos) == 4 &&
                             offsetof(Token, length) == 8 && alignof(Token) <= alignof(uint32_t);

/// Whether the words are tokens of `source`: known kinds (the padding after a kind's byte
/// zero), each beginning where the one before ended or after it (the lexer's tokens never
/// overlap), the last one the end of the template at its end, so that all lie in it.
bool fits(std::span<const uint32_t> words, std::string_view source) {
  uint64_t end = 0;  // of the token before
  for (size_t i = 0; i < words.size(); i += kWordsPerToken) {
    uint32_t kind = words[i], pos = words[i + 1], length = words[i + 2];
    if (kind > static_cast<uint32_t>(Tok::Eof) || pos < end) return false;
    end = uint64_t{pos} + length;
  }
  size_t last = words.size() - kWordsPerToken;
  return words[last] == static_cast<uint32_t>(Tok::Eof) && words[last + 1] == source.size() &&
         end == source.size();
}

}  // namespace

std::vector<uint32_t> packTokens(const std::vector<Token>& tokens) {
  std::vector<uint32_t> words;
  words.reserve(tokens.size() * kWordsPerToken);
  for (const Token& token : tokens) {
    words.push_back(static_cast<uint32_t>(token.kind));
    words.push_back(token.pos);
    words.push_back(token.length);
  }
  return words;
}

std::optional<std::span<const Token>> storedTokens(std::span<const uint32_t> words,
                                                   std::string_view source) {
  if (!kLayoutFits || words.empty() || words.size() % kWordsPerToken != 0 || !fits(words, source)) {
    return std::nullopt;
  }
  return std::span<const Token>(reinterpret_cast<const Token*>(words.data()),
                                words.size() / kWordsPerToken);
}

}  // namespace smachac::tmpl
