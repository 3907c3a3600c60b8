// The lexer (see lexer.h). It follows Jinja2's lexing rules: the earliest `{{`, `{%`, `{#`
// or `{% raw %}` opens a tag; `-` strips whitespace on that side, `+` disables lstrip;
// with lstrip_blocks, spaces before a `{%`/`{#` tag that starts a line are dropped.
#include "backends/tmpl/lexer.h"

#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

enum class TagKind { kRaw, kComment, kBlock, kVariable };

struct TagStart {
  size_t pos;  // offset of `{`
  TagKind kind;
  char sign;    // '-', '+' or 0
  size_t body;  // offset after the opener (after the whole `{% raw %}` for raw)
};

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isAsciiNameStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

class Lexer {
 public:
  Lexer(std::string_view src, const LexerOptions& options) : src_(src), options_(options) {}

  std::vector<Token> run() {
    while (pos_ < src_.size()) {
      TagStart tag;
      if (!findTag(pos_, tag)) {
        emit(Tok::kData, pos_, src_.substr(pos_));
        break;
      }
      emitLeadingData(tag);
      lexTag(tag);
    }
    emit(Tok::kEof, static_cast<uint32_t>(src_.size()), {});
    return std::move(out_);
  }

 private:
  [[noreturn]] void failAt(size_t pos, std::string message) {
    throw SyntaxFault{static_cast<uint32_t>(pos), std::move(message)};
  }

  void emit(Tok kind, size_t pos, std::string_view text) {
    out_.push_back(Token{kind, static_cast<uint32_t>(pos), text});
  }

  size_t skipSpace(size_t p) const {
    while (p < src_.size()) {
      size_t next = p;
      if (!unicode::isSpace(unicode::decode(src_, next))) break;
      p = next;
    }
    return p;
  }

  bool startsWith(size_t p, std::string_view s) const { return src_.substr(p, s.size()) == s; }

  // `{%` [-+]? \s* raw \s* (-%}\s* | %}) at p; sets the end of the match.
  bool matchRawBegin(size_t p, char& sign, size_t& end) const {
    size_t q = p + 2;
    sign = 0;
    if (q < src_.size() && (src_[q] == '-' || src_[q] == '+')) sign = src_[q++];
    q = skipSpace(q);
    if (!startsWith(q, "raw")) return false;
    q = skipSpace(q + 3);
    if (startsWith(q, "-%}")) {
      end = skipSpace(q + 3);
      return true;
    }
    if (startsWith(q, "%}")) {
      end = q + 2;
      return true;
    }
    return false;
  }

  bool findTag(size_t from, TagStart& tag) const {
    for (size_t p = src_.find('{', from); p != std::string_view::npos; p = src_.find('{', p + 1)) {
      if (p + 1 >= src_.size()) return false;
      char c = src_[p + 1];
      if (c != '%' && c != '{' && c != '#') continue;
      tag.pos = p;
      size_t end;
      if (c == '%' && matchRawBegin(p, tag.sign, end)) {
        tag.kind = TagKind::kRaw;
        tag.body = end;
        return true;
      }
      tag.kind = c == '%' ? TagKind::kBlock : c == '{' ? TagKind::kVariable : TagKind::kComment;
      char s = p + 2 < src_.size() ? src_[p + 2] : 0;
      tag.sign = (s == '-' || s == '+') ? s : 0;
      tag.body = p + 2 + (tag.sign ? 1 : 0);
      return true;
    }
    return false;
  }

  // Applies `-` stripping or lstrip_blocks to the text before a tag (Jinja's OptionalLStrip).
  std::string_view stripBeforeTag(std::string_view text, char sign, bool variable) const {
    if (sign == '-') return unicode::strip(text, false, true);
    if (sign == '+' || !options_.lstripBlocks || variable) return text;
    size_t lineStart = text.rfind('\n');
    lineStart = lineStart == std::string_view::npos ? 0 : lineStart + 1;
    if (lineStart == 0 && !lineStarting_) return text;
    std::string_view tail = text.substr(lineStart);
    if (tail.empty() || !unicode::strip(tail).empty()) return text;
    return text.substr(0, lineStart);
  }

  void emitLeadingData(const TagStart& tag) {
    std::string_view text = src_.substr(pos_, tag.pos - pos_);
    text = stripBeforeTag(text, tag.sign, tag.kind == TagKind::kVariable);
    if (!text.empty()) emit(Tok::kData, pos_, text);
  }

  void lexTag(const TagStart& tag) {
    switch (tag.kind) {
      case TagKind::kRaw:
        return lexRaw(tag);
      case TagKind::kComment:
        return lexComment(tag);
      case TagKind::kBlock:
      case TagKind::kVariable:
        return lexCode(tag);
    }
  }

  void finish(size_t end) {
    lineStarting_ = end > 0 && src_[end - 1] == '\n';
    pos_ = end;
  }

  void lexComment(const TagStart& tag) {
    for (size_t i = tag.body; i < src_.size(); ++i) {
      if (startsWith(i, "+#}")) return finish(i + 3);
      if (startsWith(i, "-#}")) return finish(skipSpace(i + 3));
      if (startsWith(i, "#}")) return finish(i + 2);
    }
    failAt(tag.pos, "missing end of comment tag");
  }

  void lexRaw(const TagStart& tag) {
    lineStarting_ = tag.body > 0 && src_[tag.body - 1] == '\n';
    for (size_t p = src_.find("{%", tag.body); p != std::string_view::npos;
         p = src_.find("{%", p + 1)) {
      size_t q = p + 2;
      char sign = 0;
      if (q < src_.size() && (src_[q] == '-' || src_[q] == '+')) sign = src_[q++];
      q = skipSpace(q);
      if (!startsWith(q, "endraw")) continue;
      q = skipSpace(q + 6);
      size_t end = 0;
      if (startsWith(q, "+%}")) {
        end = q + 3;
      } else if (startsWith(q, "-%}")) {
        end = skipSpace(q + 3);
      } else if (startsWith(q, "%}")) {
        end = q + 2;
      } else {
        continue;
      }
      std::string_view text = stripBeforeTag(src_.substr(tag.body, p - tag.body), sign, false);
      if (!text.empty()) emit(Tok::kData, tag.body, text);
      return finish(end);
    }
    failAt(tag.pos, "missing end of raw directive");
  }

  // Matches the end of a `{{ }}` or `{% %}` tag at pos_.
  bool matchEnd(bool variable, size_t& end) const {
    if (variable) {
      if (startsWith(pos_, "-}}")) return end = skipSpace(pos_ + 3), true;
      if (startsWith(pos_, "}}")) return end = pos_ + 2, true;
      return false;
    }
    if (startsWith(pos_, "+%}")) return end = pos_ + 3, true;
    if (startsWith(pos_, "-%}")) return end = skipSpace(pos_ + 3), true;
    if (startsWith(pos_, "%}")) return end = pos_ + 2, true;
    return false;
  }

  void lexCode(const TagStart& tag) {
    bool variable = tag.kind == TagKind::kVariable;
    emit(variable ? Tok::kVariableBegin : Tok::kBlockBegin, tag.pos,
         src_.substr(tag.pos, tag.body - tag.pos));
    pos_ = tag.body;
    balance_.clear();
    while (pos_ < src_.size()) {
      size_t end;
      if (balance_.empty() && matchEnd(variable, end)) {
        emit(variable ? Tok::kVariableEnd : Tok::kBlockEnd, pos_, src_.substr(pos_, end - pos_));
        return finish(end);
      }
      lexCodeToken();
    }
  }

  void lexCodeToken() {
    size_t next = pos_;
    char32_t cp = unicode::decode(src_, next);
    if (unicode::isSpace(cp)) {
      pos_ = skipSpace(pos_);
      return;
    }
    if (lexFloat() || lexInteger() || lexName() || lexString() || lexOperator()) return;
    std::string shown;
    unicode::encode(shown, cp);
    failAt(pos_, "unexpected char `" + shown + "`");
  }

  // (\d+_)*\d+
  bool digits(size_t& p) const {
    if (p >= src_.size() || !isDigit(src_[p])) return false;
    while (p < src_.size() && isDigit(src_[p])) ++p;
    while (p + 1 < src_.size() && src_[p] == '_' && isDigit(src_[p + 1])) {
      p += 1;
      while (p < src_.size() && isDigit(src_[p])) ++p;
    }
    return true;
  }

  bool exponent(size_t& p) const {
    if (p >= src_.size() || (src_[p] != 'e' && src_[p] != 'E')) return false;
    size_t q = p + 1;
    if (q < src_.size() && (src_[q] == '+' || src_[q] == '-')) ++q;
    if (!digits(q)) return false;
    p = q;
    return true;
  }

  bool lexFloat() {
    if (pos_ > 0 && src_[pos_ - 1] == '.') return false;
    size_t p = pos_;
    if (!digits(p)) return false;
    size_t withFraction = p;
    bool hasFraction = false;
    if (withFraction < src_.size() && src_[withFraction] == '.') {
      size_t q = withFraction + 1;
      if (digits(q)) {
        withFraction = q;
        hasFraction = true;
      }
    }
    size_t end = withFraction;
    if (!exponent(end)) {
      if (!hasFraction) return false;
      end = withFraction;
    }
    emit(Tok::kFloat, pos_, src_.substr(pos_, end - pos_));
    pos_ = end;
    return true;
  }

  bool prefixedDigits(size_t& p, std::string_view allowed) const {
    size_t count = 0;
    while (p < src_.size()) {
      size_t q = p;
      if (src_[q] == '_') ++q;
      if (q >= src_.size() ||
          allowed.find(static_cast<char>(src_[q] | 0x20)) == std::string_view::npos)
        break;
      p = q + 1;
      ++count;
    }
    return count > 0;
  }

  bool lexInteger() {
    size_t p = pos_;
    if (p >= src_.size() || !isDigit(src_[p])) return false;
    if (src_[p] == '0' && p + 1 < src_.size()) {
      char base = static_cast<char>(src_[p + 1] | 0x20);
      size_t q = p + 2;
      std::string_view allowed = base == 'b'   ? "01"
                                 : base == 'o' ? "01234567"
                                 : base == 'x' ? "0123456789abcdef"
                                               : "";
      if (!allowed.empty() && prefixedDigits(q, allowed)) {
        emit(Tok::kInteger, pos_, src_.substr(pos_, q - pos_));
        pos_ = q;
        return true;
      }
    }
    if (src_[p] == '0') {
      ++p;
      while (p < src_.size()) {
        size_t q = p + (src_[p] == '_' ? 1 : 0);
        if (q >= src_.size() || src_[q] != '0') break;
        p = q + 1;
      }
    } else {
      ++p;
      while (p < src_.size()) {
        size_t q = p + (src_[p] == '_' ? 1 : 0);
        if (q >= src_.size() || !isDigit(src_[q])) break;
        p = q + 1;
      }
    }
    emit(Tok::kInteger, pos_, src_.substr(pos_, p - pos_));
    pos_ = p;
    return true;
  }

  bool isNameChar(size_t p, size_t& next, bool start) const {
    next = p;
    char c = src_[p];
    if (static_cast<unsigned char>(c) < 0x80) {
      next = p + 1;
      return isAsciiNameStart(c) || (!start && isDigit(c));
    }
    char32_t cp = unicode::decode(src_, next);
    return unicode::isAlnum(cp);
  }

  bool lexName() {
    size_t next;
    if (!isNameChar(pos_, next, true)) return false;
    size_t p = next;
    while (p < src_.size() && isNameChar(p, next, false)) p = next;
    emit(Tok::kName, pos_, src_.substr(pos_, p - pos_));
    pos_ = p;
    return true;
  }

  bool lexString() {
    char quote = src_[pos_];
    if (quote != '\'' && quote != '"') return false;
    size_t p = pos_ + 1;
    while (p < src_.size() && src_[p] != quote) p += src_[p] == '\\' ? 2 : 1;
    if (p >= src_.size()) return false;
    emit(Tok::kString, pos_, src_.substr(pos_, p + 1 - pos_));
    pos_ = p + 1;
    return true;
  }

  bool lexOperator() {
    struct Op {
      std::string_view text;
      Tok kind;
    };
    static constexpr Op kOps[] = {
        {"**", Tok::kPow},     {"//", Tok::kFloorDiv}, {"==", Tok::kEq},    {"!=", Tok::kNe},
        {">=", Tok::kGe},      {"<=", Tok::kLe},       {"+", Tok::kAdd},    {"-", Tok::kSub},
        {"/", Tok::kDiv},      {"*", Tok::kMul},       {"%", Tok::kMod},    {"~", Tok::kTilde},
        {"[", Tok::kLBracket}, {"]", Tok::kRBracket},  {"(", Tok::kLParen}, {")", Tok::kRParen},
        {"{", Tok::kLBrace},   {"}", Tok::kRBrace},    {">", Tok::kGt},     {"<", Tok::kLt},
        {"=", Tok::kAssign},   {".", Tok::kDot},       {":", Tok::kColon},  {"|", Tok::kPipe},
        {",", Tok::kComma},    {";", Tok::kSemicolon},
    };
    for (const Op& op : kOps) {
      if (!startsWith(pos_, op.text)) continue;
      balanceBracket(op.text[0]);
      emit(op.kind, pos_, src_.substr(pos_, op.text.size()));
      pos_ += op.text.size();
      return true;
    }
    return false;
  }

  void balanceBracket(char c) {
    if (c == '{' || c == '(' || c == '[') {
      balance_.push_back(c == '{' ? '}' : c == '(' ? ')' : ']');
      return;
    }
    if (c != '}' && c != ')' && c != ']') return;
    if (balance_.empty()) failAt(pos_, std::string("unexpected `") + c + "`");
    char expected = balance_.back();
    balance_.pop_back();
    if (expected != c) {
      failAt(pos_, std::string("unexpected `") + c + "`, expected `" + expected + "`");
    }
  }

  std::string_view src_;
  LexerOptions options_;
  size_t pos_ = 0;
  bool lineStarting_ = true;
  std::vector<char> balance_;
  std::vector<Token> out_;
};

}  // namespace

std::string normalizeSource(std::string_view source) {
  std::string out;
  out.reserve(source.size());
  for (size_t i = 0; i < source.size(); ++i) {
    if (source[i] == '\r') {
      out.push_back('\n');
      if (i + 1 < source.size() && source[i + 1] == '\n') ++i;
    } else {
      out.push_back(source[i]);
    }
  }
  if (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

std::vector<Token> tokenize(std::string_view source, const LexerOptions& options) {
  return Lexer(source, options).run();
}

std::string_view describe(Tok kind) {
  switch (kind) {
    case Tok::kData:
      return "template data";
    case Tok::kVariableBegin:
      return "{{";
    case Tok::kVariableEnd:
      return "}}";
    case Tok::kBlockBegin:
      return "{%";
    case Tok::kBlockEnd:
      return "%}";
    case Tok::kName:
      return "name";
    case Tok::kString:
      return "string";
    case Tok::kInteger:
      return "integer";
    case Tok::kFloat:
      return "float";
    case Tok::kEof:
      return "end of template";
    case Tok::kAdd:
      return "+";
    case Tok::kSub:
      return "-";
    case Tok::kMul:
      return "*";
    case Tok::kDiv:
      return "/";
    case Tok::kFloorDiv:
      return "//";
    case Tok::kMod:
      return "%";
    case Tok::kPow:
      return "**";
    case Tok::kTilde:
      return "~";
    case Tok::kLBracket:
      return "[";
    case Tok::kRBracket:
      return "]";
    case Tok::kLParen:
      return "(";
    case Tok::kRParen:
      return ")";
    case Tok::kLBrace:
      return "{";
    case Tok::kRBrace:
      return "}";
    case Tok::kEq:
      return "==";
    case Tok::kNe:
      return "!=";
    case Tok::kGt:
      return ">";
    case Tok::kGe:
      return ">=";
    case Tok::kLt:
      return "<";
    case Tok::kLe:
      return "<=";
    case Tok::kAssign:
      return "=";
    case Tok::kDot:
      return ".";
    case Tok::kColon:
      return ":";
    case Tok::kPipe:
      return "|";
    case Tok::kComma:
      return ",";
    case Tok::kSemicolon:
      return ";";
  }
  return "token";
}

}  // namespace smachac::tmpl
