// Tokens of the template language. Token text is a view into the template's (owned,
// normalised) source; `pos` is the byte offset used for error locations.
#pragma once

#include <cstdint>
#include <string_view>

namespace smachac::tmpl {

enum class Tok : uint8_t {
  kData,
  kVariableBegin,
  kVariableEnd,
  kBlockBegin,
  kBlockEnd,
  kName,
  kString,
  kInteger,
  kFloat,
  kAdd,
  kSub,
  kMul,
  kDiv,
  kFloorDiv,
  kMod,
  kPow,
  kTilde,
  kLBracket,
  kRBracket,
  kLParen,
  kRParen,
  kLBrace,
  kRBrace,
  kEq,
  kNe,
  kGt,
  kGe,
  kLt,
  kLe,
  kAssign,
  kDot,
  kColon,
  kPipe,
  kComma,
  kSemicolon,
  kEof,
};

struct Token {
  Tok kind;
  uint32_t pos;
  std::string_view text;

  bool is(Tok k) const { return kind == k; }
  bool isName(std::string_view name) const { return kind == Tok::kName && text == name; }
};

/// How a token is described in error messages (`end of statement block`, `)`, a name...).
std::string_view describe(Tok kind);

}  // namespace smachac::tmpl
