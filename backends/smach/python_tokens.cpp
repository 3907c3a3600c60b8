// tokenizePython (python_tokens.h).
#include "backends/smach/python_tokens.h"

#include <array>
#include <cctype>

#include "ir/support/python_keywords.h"

namespace smachac::backends {
namespace {

// Longest first, so that the first match is the longest.
constexpr std::array<std::string_view, 47> kOperators = {
    "**=", "//=", ">>=", "<<=", "...", "->", ":=", "**", "//", "<<", ">>", "<=",
    ">=",  "==",  "!=",  "+=",  "-=",  "*=", "/=", "%=", "&=", "|=", "^=", "@=",
    "+",   "-",   "*",   "/",   "%",   "@",  "&",  "|",  "^",  "~",  "<",  ">",
    "(",   ")",   "[",   "]",   "{",   "}",  ",",  ":",  ".",  ";",  "="};

constexpr size_t kMaxNesting = 200;  // CPython's tokenizer's limit

bool isNameStart(unsigned char c) { return std::isalpha(c) || c == '_' || c >= 0x80; }
bool isNameChar(unsigned char c) { return isNameStart(c) || std::isdigit(c); }

class Lexer {
 public:
  explicit Lexer(std::string_view code) : code_(code) {}

  PythonTokens run() {
    while (!result_.error) {
      skipBlanks();
      if (pos_ >= code_.size()) break;
      if (!next()) break;
    }
    if (!result_.error && depth_ > 0) fail(code_.size(), "unclosed bracket");
    result_.tokens.push_back({PythonTokenKind::End, {}, code_.size()});
    return std::move(result_);
  }

 private:
  char at(size_t i) const { return i < code_.size() ? code_[i] : '\0'; }

  void fail(size_t offset, std::string message) {
    if (!result_.error) result_.error = PythonTokenError{offset, std::move(message)};
  }

  void push(PythonTokenKind kind, size_t start) {
    result_.tokens.push_back({kind, code_.substr(start, pos_ - start), start});
  }

  // Spaces, comments, continuations; line breaks inside brackets. A line break outside them
  // ends the expression: only blank lines and comments may follow.
  void skipBlanks() {
    while (pos_ < code_.size()) {
      const char c = code_[pos_];
      if (c == ' ' || c == '\t' || c == '\f') {
        ++pos_;
      } else if (c == '#') {
        while (pos_ < code_.size() && code_[pos_] != '\n') ++pos_;
      } else if (c == '\\' && (at(pos_ + 1) == '\n' || (at(pos_ + 1) == '\r'))) {
        pos_ += at(pos_ + 1) == '\r' && at(pos_ + 2) == '\n' ? 3 : 2;
      } else if (c == '\n' || c == '\r') {
        if (depth_ == 0) ended_ = true;
        ++pos_;
      } else {
        if (ended_) fail(pos_, "the expression ended at the line break before this");
        return;
      }
    }
  }

  bool next() {
    const unsigned char c = static_cast<unsigned char>(code_[pos_]);
    if (std::isdigit(c) || (c == '.' && std::isdigit(static_cast<unsigned char>(at(pos_ + 1))))) {
      return number();
    }
    if (isNameStart(c)) return nameOrString();
    if (c == '"' || c == '\'') return string(pos_);
    return operatorToken();
  }

  bool nameOrString() {
    const size_t start = pos_;
    while (pos_ < code_.size() && isNameChar(static_cast<unsigned char>(code_[pos_]))) ++pos_;
    if ((at(pos_) == '"' || at(pos_) == '\'') &&
        isStringPrefix(code_.substr(start, pos_ - start))) {
      return string(start);
    }
    const std::string_view word = code_.substr(start, pos_ - start);
    push(isPythonKeyword(word) ? PythonTokenKind::Keyword : PythonTokenKind::Name, start);
    return true;
  }

  static bool isStringPrefix(std::string_view prefix) {
    std::string lower;
    for (char c : prefix) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (std::string_view valid : {"r", "u", "b", "f", "br", "rb", "fr", "rf"}) {
      if (lower == valid) return true;
    }
    return false;
  }

  // A string from its prefix at `start`; pos_ is at the opening quote.
  bool string(size_t start) {
    const char quote = code_[pos_];
    const bool triple = at(pos_ + 1) == quote && at(pos_ + 2) == quote;
    pos_ += triple ? 3 : 1;
    while (pos_ < code_.size()) {
      const char c = code_[pos_];
      if (c == '\\') {
        pos_ += 2;
      } else if (c == quote && (!triple || (at(pos_ + 1) == quote && at(pos_ + 2) == quote))) {
        pos_ += triple ? 3 : 1;
        push(PythonTokenKind::String, start);
        return true;
      } else if ((c == '\n' || c == '\r') && !triple) {
        break;
      } else {
        ++pos_;
      }
    }
    fail(start, "unterminated string");
    return false;
  }

  bool digits(bool (*is_digit_of)(unsigned char)) {
    const size_t start = pos_;
    while (pos_ < code_.size()) {
      const unsigned char c = static_cast<unsigned char>(code_[pos_]);
      if (is_digit_of(c)) {
        ++pos_;
      } else if (c == '_' && pos_ > start &&
                 is_digit_of(static_cast<unsigned char>(at(pos_ + 1)))) {
        ++pos_;
      } else {
        break;
      }
    }
    return pos_ > start;
  }

  static bool decimal(unsigned char c) { return c >= '0' && c <= '9'; }
  static bool hex(unsigned char c) { return std::isxdigit(c) != 0; }
  static bool octal(unsigned char c) { return c >= '0' && c <= '7'; }
  static bool binary(unsigned char c) { return c == '0' || c == '1'; }

  bool number() {
    const size_t start = pos_;
    const char base = static_cast<char>(std::tolower(static_cast<unsigned char>(at(pos_ + 1))));
    if (code_[pos_] == '0' && (base == 'x' || base == 'o' || base == 'b')) {
      pos_ += 2;
      const bool ok = at(pos_) == '_' ? (++pos_, true) : true;
      if (!ok || !digits(base == 'x' ? hex : base == 'o' ? octal : binary)) {
        fail(start, "invalid number");
        return false;
      }
      return endNumber(start);
    }
    const bool whole = digits(decimal);
    bool fraction = false;
    if (at(pos_) == '.') {
      ++pos_;
      fraction = true;
      digits(decimal);
    }
    if (std::tolower(static_cast<unsigned char>(at(pos_))) == 'e') {
      size_t exponent = pos_ + 1;
      if (at(exponent) == '+' || at(exponent) == '-') ++exponent;
      if (decimal(static_cast<unsigned char>(at(exponent)))) {
        pos_ = exponent;
        digits(decimal);
        fraction = true;
      }
    }
    if (whole && !fraction && std::tolower(static_cast<unsigned char>(at(pos_))) != 'j' &&
        !leadingZerosAllowed(code_.substr(start, pos_ - start))) {
      fail(start, "leading zeros in a decimal integer");
      return false;
    }
    if (std::tolower(static_cast<unsigned char>(at(pos_))) == 'j') ++pos_;
    return endNumber(start);
  }

  // `012` is an error, `00` and `0_0` are not.
  static bool leadingZerosAllowed(std::string_view text) {
    if (text.size() < 2 || text[0] != '0') return true;
    return text.find_first_not_of("0_") == std::string_view::npos;
  }

  // A number may not run into a name, except a keyword (`1if x else 2`).
  bool endNumber(size_t start) {
    if (pos_ < code_.size() && isNameChar(static_cast<unsigned char>(code_[pos_]))) {
      size_t end = pos_;
      while (end < code_.size() && isNameChar(static_cast<unsigned char>(code_[end]))) ++end;
      if (!isPythonKeyword(code_.substr(pos_, end - pos_))) {
        fail(start, "invalid number");
        return false;
      }
    }
    push(PythonTokenKind::Number, start);
    return true;
  }

  bool operatorToken() {
    for (std::string_view op : kOperators) {
      if (code_.substr(pos_, op.size()) == op) {
        const size_t start = pos_;
        pos_ += op.size();
        trackBrackets(op, start);
        push(PythonTokenKind::Operator, start);
        return !result_.error;
      }
    }
    fail(pos_, "unexpected character `" + std::string(1, code_[pos_]) + "`");
    return false;
  }

  void trackBrackets(std::string_view op, size_t start) {
    if (op == "(" || op == "[" || op == "{") {
      if (brackets_.size() == kMaxNesting) fail(start, "too many nested brackets");
      brackets_.push_back(op[0]);
    } else if (op == ")" || op == "]" || op == "}") {
      const char open = op == ")" ? '(' : op == "]" ? '[' : '{';
      if (brackets_.empty() || brackets_.back() != open) {
        fail(start, "unmatched `" + std::string(op) + "`");
        return;
      }
      brackets_.pop_back();
    }
    depth_ = brackets_.size();
  }

  std::string_view code_;
  size_t pos_ = 0;
  std::string brackets_;
  size_t depth_ = 0;
  bool ended_ = false;
  PythonTokens result_;
};

}  // namespace

PythonTokens tokenizePython(std::string_view code) { return Lexer(code).run(); }

}  // namespace smachac::backends
