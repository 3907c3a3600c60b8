// Tokens of the template language. Token text is a view into the template's (owned,
// normalised) source; `pos` is the byte offset used for error locations.
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

struct Token {
  Tok kind;
  uint32_t pos;
  std::string_view text;

  bool is(Tok k) const { return kind == k; }
  bool isName(std::string_view name) const { return kind == Tok::Name && text == name; }
};

/// How a token is described in error messages (`end of statement block`, `)`, a name...).
std::string_view describe(Tok kind);

}  // namespace smachac::tmpl
