// The lexer of portable expressions.
#include "frontend/expr_lexer.h"

#include <fmt/core.h>

#include <array>
#include <charconv>
#include <cstdlib>

namespace smachac::frontend {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isNameStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isNameChar(char c) { return isNameStart(c) || isDigit(c); }

int hexDigit(char c) {
  if (isDigit(c)) return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

void appendUtf8(std::string& out, uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

/// Two- and one-character operators, longest first.
constexpr std::array<std::string_view, 16> kOperators{"//", "==", "!=", "<=", ">=", "+", "-", "*",
                                                      "/",  "%",  "<",  ">",  "(",  ")", ",", "="};

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  ExprTokens run() {
    ExprTokens out;
    while (true) {
      skipSpace();
      size_t start = pos_;
      ExprToken token = next();
      if (error_) {
        pos_ = start;
        out.tokens.push_back(this->token(ExprTokenKind::End, start));
        out.error = std::move(error_);
        return out;
      }
      bool end = token.kind == ExprTokenKind::End;
      out.tokens.push_back(std::move(token));
      if (end) return out;
    }
  }

 private:
  void skipSpace() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                   text_[pos_] == '\n' || text_[pos_] == '\r')) {
      ++pos_;
    }
  }

  ExprToken next() {
    size_t start = pos_;
    if (pos_ == text_.size()) return token(ExprTokenKind::End, start);
    char c = text_[pos_];
    if (isDigit(c) || (c == '.' && pos_ + 1 < text_.size() && isDigit(text_[pos_ + 1]))) {
      return number();
    }
    if (c == '\'' || c == '"') return string();
    if (isNameStart(c)) {
      while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
      return token(ExprTokenKind::Name, start);
    }
    for (std::string_view op : kOperators) {
      if (text_.substr(pos_).starts_with(op)) {
        pos_ += op.size();
        return token(ExprTokenKind::Operator, start);
      }
    }
    fail(fmt::format("unexpected character `{}`", characterAt(pos_)), pos_, 1);
    return {};
  }

  ExprToken number() {
    size_t start = pos_;
    while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
    bool is_float = false;
    if (pos_ < text_.size() && text_[pos_] == '.') {
      is_float = true;
      ++pos_;
      while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      size_t exponent = pos_ + 1;
      if (exponent < text_.size() && (text_[exponent] == '+' || text_[exponent] == '-')) {
        ++exponent;
      }
      if (exponent < text_.size() && isDigit(text_[exponent])) {
        is_float = true;
        pos_ = exponent;
        while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
      }
    }
    if (pos_ < text_.size() && isNameChar(text_[pos_])) {
      while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
      fail(fmt::format("`{}` is not a number", text_.substr(start, pos_ - start)), start,
           pos_ - start);
      return {};
    }
    ExprToken t = token(ExprTokenKind::Number, start);
    t.value = is_float ? floatValue(t.text) : intValue(t);
    return t;
  }

  ir::Value floatValue(std::string_view text) {
    return ir::Value::real(std::strtod(std::string(text).c_str(), nullptr));
  }

  ir::Value intValue(const ExprToken& t) {
    if (t.text.size() > 1 && t.text[0] == '0' && t.text.find_first_not_of('0') != t.text.npos) {
      fail(fmt::format("`{}`: integers do not start with 0 (Python reads no octal this way)",
                       t.text),
           t.offset, t.length);
      return {};
    }
    int64_t v = 0;
    auto [end, error] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (error != std::errc()) {
      fail(fmt::format("integer `{}` does not fit in 64 bits", t.text), t.offset, t.length);
    }
    return ir::Value::integer(v);
  }

  ExprToken string() {
    size_t start = pos_;
    char quote = text_[pos_++];
    std::string decoded;
    while (pos_ < text_.size() && text_[pos_] != quote) {
      if (text_[pos_] == '\n') break;
      if (text_[pos_] != '\\') {
        decoded += text_[pos_++];
      } else if (!escape(decoded)) {
        return {};
      }
    }
    if (pos_ >= text_.size() || text_[pos_] != quote) {
      fail("string not closed on its line", start, pos_ - start);
      return {};
    }
    ++pos_;
    ExprToken t = token(ExprTokenKind::String, start);
    t.value = ir::Value::string(std::move(decoded));
    return t;
  }

  /// Decodes the escape at pos_ into `out`; false after reporting a bad one.
  bool escape(std::string& out) {
    size_t start = pos_;
    if (pos_ + 1 >= text_.size()) {
      fail("string not closed on its line", start, 1);
      return false;
    }
    char c = text_[pos_ + 1];
    pos_ += 2;
    switch (c) {
      case '\\':
      case '\'':
      case '"':
        out += c;
        return true;
      case 'n':
        out += '\n';
        return true;
      case 't':
        out += '\t';
        return true;
      case 'r':
        out += '\r';
        return true;
      case '0':
        out += '\0';
        return true;
      case 'x':
        return hexEscape(out, start, 2);
      case 'u':
        return hexEscape(out, start, 4);
      default:
        fail(fmt::format("unknown escape `\\{}`", characterAt(start + 1)), start, 2);
        return false;
    }
  }

  bool hexEscape(std::string& out, size_t start, size_t digits) {
    uint32_t code = 0;
    for (size_t i = 0; i < digits; ++i) {
      int d = pos_ < text_.size() ? hexDigit(text_[pos_]) : -1;
      if (d < 0) {
        fail(fmt::format("`\\{}` needs {} hex digits", text_[start + 1], digits), start,
             pos_ - start);
        return false;
      }
      code = code * 16 + static_cast<uint32_t>(d);
      ++pos_;
    }
    if (code >= 0xD800 && code <= 0xDFFF) {
      fail("a surrogate code point is no character", start, pos_ - start);
      return false;
    }
    appendUtf8(out, code);
    return true;
  }

  std::string_view characterAt(size_t i) const {
    unsigned char c = static_cast<unsigned char>(text_[i]);
    size_t length = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
    return text_.substr(i, length);
  }

  ExprToken token(ExprTokenKind kind, size_t start) const {
    ExprToken t;
    t.kind = kind;
    t.offset = static_cast<uint32_t>(start);
    t.length = static_cast<uint32_t>(pos_ - start);
    t.text = text_.substr(start, pos_ - start);
    return t;
  }

  void fail(std::string message, size_t offset, size_t length) {
    if (!error_) {
      error_ = ExprSyntaxError{std::move(message), static_cast<uint32_t>(offset),
                               static_cast<uint32_t>(std::max<size_t>(length, 1))};
    }
  }

  std::string_view text_;
  size_t pos_ = 0;
  std::optional<ExprSyntaxError> error_;
};

}  // namespace

ExprTokens lexExpr(std::string_view text) { return Lexer(text).run(); }

}  // namespace smachac::frontend
