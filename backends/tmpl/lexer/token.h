// Tokens of the template language. A token is its kind and where it lies in the template's
// normalised source: `pos`, the byte offset (also what error locations give), and `length`;
// its text is read from that source (`textIn`), so a token is 12 bytes and the build's stored
// tokens (token_table.h) become tokens without a view to make for each. The build stores a
// token as the three 32-bit words of this struct's layout (kind with zero padding, offset,
// length), which the engine reads in place: hence `may_alias` (those words are `uint32_t`s).
#pragma once

#include <cstdint>
#include <string_view>

namespace smachac::tmpl {

enum class Tok : uint8_t {
  Data,
  VariableBegin,
  VariableEnd,
  BlockBegin,
  BlockEnd,
  Name,
  String,
  Integer,
  Float,
  Add,
  Sub,
  Mul,
  Div,
  FloorDiv,
  Mod,
  Pow,
  Tilde,
  LBracket,
  RBracket,
  LParen,
  RParen,
  LBrace,
  RBrace,
  Eq,
  Ne,
  Gt,
  Ge,
  Lt,
  Le,
  Assign,
  Dot,
  Colon,
  Pipe,
  Comma,
  Semicolon,
  Eof,
};

struct [[gnu::may_alias]] Token {
  Tok kind;
  uint32_t pos;
  uint32_t length;

  bool is(Tok k) const { return kind == k; }
  /// The token's text in `source`, the normalised source it was made of.
  std::string_view textIn(std::string_view source) const {
    return std::string_view(source.data() + pos, length);
  }
};

/// How a token is described in error messages (`end of statement block`, `)`, a name...).
std::string_view describe(Tok kind);

}  // namespace smachac::tmpl
