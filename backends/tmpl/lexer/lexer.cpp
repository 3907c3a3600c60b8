// The lexer (see lexer.h). It follows Jinja2's lexing rules: the earliest `{{`, `{%`, `{#`
// or `{% raw %}` opens a tag; `-` strips whitespace on that side, `+` disables lstrip;
// with lstrip_blocks, spaces before a `{%`/`{#` tag that starts a line are dropped.
#include "backends/tmpl/lexer/lexer.h"

#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

enum class TagKind { Raw, Comment, Block, Variable };

struct TagStart {
  size_t pos;  // offset of `{`
  TagKind kind;
  char sign;    // '-', '+' or 0
  size_t body;  // offset after the opener (after the whole `{% raw %}` for raw)
};

bool isDigit(char c) { return c >= '0' && c <= '9'; }
// Python's str.isspace for one ASCII byte (unicode::isSpace without decoding).
bool isAsciiSpace(unsigned char c) { return (c >= 0x09 && c <= 0x0D) || (c >= 0x1C && c <= 0x20); }
bool isAsciiNameStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

class Lexer {
 public:
  Lexer(std::string_view src, const LexerOptions& options) : src_(src), options_(options) {}

  std::vector<Token> run() {
    out_.reserve(src_.size() / 6 + 16);  // templates run about 8 bytes a token
    while (pos_ < src_.size()) {
      TagStart tag;
      if (!findTag(pos_, tag)) {
        emit(Tok::Data, pos_, src_.substr(pos_));
        break;
      }
      emitLeadingData(tag);
      lexTag(tag);
    }
    emit(Tok::Eof, static_cast<uint32_t>(src_.size()), {});
    return std::move(out_);
  }

 private:
  [[noreturn]] void failAt(size_t pos, std::string message) {
    throw SyntaxFault{static_cast<uint32_t>(pos), std::move(message)};
  }

  // `text` starts at `pos` (a token is its position and length in the source).
  void emit(Tok kind, size_t pos, std::string_view text) {
    out_.push_back(Token{kind, static_cast<uint32_t>(pos), static_cast<uint32_t>(text.size())});
  }

  size_t skipSpace(size_t p) const {
    while (p < src_.size()) {
      auto byte = static_cast<unsigned char>(src_[p]);
      if (byte < 0x80) {
        if (!isAsciiSpace(byte)) break;
        ++p;
        continue;
      }
      size_t next = p;
      if (!unicode::isSpace(unicode::decode(src_, next))) break;
      p = next;
    }
    return p;
  }

  // A byte loop: the patterns are two or three characters, shorter than a call to memcmp.
  bool startsWith(size_t p, std::string_view s) const {
    if (p > src_.size() || src_.size() - p < s.size()) return false;
    for (size_t i = 0; i < s.size(); ++i) {
      if (src_[p + i] != s[i]) return false;
    }
    return true;
  }

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
        tag.kind = TagKind::Raw;
        tag.body = end;
        return true;
      }
      tag.kind = c == '%' ? TagKind::Block : c == '{' ? TagKind::Variable : TagKind::Comment;
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
    if (sign == '+' || !options_.lstrip_blocks || variable) return text;
    size_t line_start = text.rfind('\n');
    line_start = line_start == std::string_view::npos ? 0 : line_start + 1;
    if (line_start == 0 && !line_starting_) return text;
    std::string_view tail = text.substr(line_start);
    if (tail.empty() || !unicode::strip(tail).empty()) return text;
    return text.substr(0, line_start);
  }

  void emitLeadingData(const TagStart& tag) {
    std::string_view text = src_.substr(pos_, tag.pos - pos_);
    text = stripBeforeTag(text, tag.sign, tag.kind == TagKind::Variable);
    if (!text.empty()) emit(Tok::Data, pos_, text);
  }

  void lexTag(const TagStart& tag) {
    switch (tag.kind) {
      case TagKind::Raw:
        return lexRaw(tag);
      case TagKind::Comment:
        return lexComment(tag);
      case TagKind::Block:
      case TagKind::Variable:
        return lexCode(tag);
    }
  }

  void finish(size_t end) {
    line_starting_ = end > 0 && src_[end - 1] == '\n';
    pos_ = end;
  }

  // The comment ends at the first `#}`, with the `-` or `+` just before it if inside it.
  void lexComment(const TagStart& tag) {
    size_t end = src_.find("#}", tag.body);
    if (end == std::string_view::npos) failAt(tag.pos, "missing end of comment tag");
    char sign = end > tag.body ? src_[end - 1] : 0;
    if (sign == '+') return finish(end + 2);
    if (sign == '-') return finish(skipSpace(end + 2));
    finish(end + 2);
  }

  void lexRaw(const TagStart& tag) {
    line_starting_ = tag.body > 0 && src_[tag.body - 1] == '\n';
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
      if (!text.empty()) emit(Tok::Data, tag.body, text);
      return finish(end);
    }
    failAt(tag.pos, "missing end of raw directive");
  }

  // Matches the end of a `{{ }}` or `{% %}` tag at pos_.
  bool matchEnd(bool variable, size_t& end) const {
    char first = src_[pos_];
    if (first != '}' && first != '%' && first != '-' && first != '+') return false;
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
    bool variable = tag.kind == TagKind::Variable;
    emit(variable ? Tok::VariableBegin : Tok::BlockBegin, tag.pos,
         src_.substr(tag.pos, tag.body - tag.pos));
    pos_ = tag.body;
    balance_.clear();
    while (pos_ < src_.size()) {
      size_t end;
      if (balance_.empty() && matchEnd(variable, end)) {
        emit(variable ? Tok::VariableEnd : Tok::BlockEnd, pos_, src_.substr(pos_, end - pos_));
        return finish(end);
      }
      lexCodeToken();
    }
  }

  void lexCodeToken() {
    auto byte = static_cast<unsigned char>(src_[pos_]);
    if (isAsciiNameStart(static_cast<char>(byte))) {
      lexName();
      return;
    }
    size_t next = pos_;
    char32_t cp = byte < 0x80 ? byte : unicode::decode(src_, next);
    if (byte < 0x80 ? isAsciiSpace(byte) : unicode::isSpace(cp)) {
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
    size_t with_fraction = p;
    bool has_fraction = false;
    if (with_fraction < src_.size() && src_[with_fraction] == '.') {
      size_t q = with_fraction + 1;
      if (digits(q)) {
        with_fraction = q;
        has_fraction = true;
      }
    }
    size_t end = with_fraction;
    if (!exponent(end)) {
      if (!has_fraction) return false;
      end = with_fraction;
    }
    emit(Tok::Float, pos_, src_.substr(pos_, end - pos_));
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
        emit(Tok::Integer, pos_, src_.substr(pos_, q - pos_));
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
    emit(Tok::Integer, pos_, src_.substr(pos_, p - pos_));
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
    while (p < src_.size()) {
      char c = src_[p];
      if (isAsciiNameStart(c) || isDigit(c)) {
        ++p;
      } else if (static_cast<unsigned char>(c) >= 0x80 && isNameChar(p, next, false)) {
        p = next;
      } else {
        break;
      }
    }
    emit(Tok::Name, pos_, src_.substr(pos_, p - pos_));
    pos_ = p;
    return true;
  }

  bool lexString() {
    char quote = src_[pos_];
    if (quote != '\'' && quote != '"') return false;
    size_t p = pos_ + 1;
    while (p < src_.size() && src_[p] != quote) p += src_[p] == '\\' ? 2 : 1;
    if (p >= src_.size()) return false;
    emit(Tok::String, pos_, src_.substr(pos_, p + 1 - pos_));
    pos_ = p + 1;
    return true;
  }

  bool lexOperator() {
    size_t length = 0;
    Tok kind = operatorAt(pos_, length);
    if (length == 0) return false;
    balanceBracket(src_[pos_]);
    emit(kind, pos_, src_.substr(pos_, length));
    pos_ += length;
    return true;
  }

  // The operator at p and its length (0 when there is none); two-character ones first.
  Tok operatorAt(size_t p, size_t& length) const {
    char second = p + 1 < src_.size() ? src_[p + 1] : 0;
    auto pair = [&](char want, Tok two, Tok one) {
      length = second == want ? 2 : 1;
      return second == want ? two : one;
    };
    length = 1;
    switch (src_[p]) {
      case '*':
        return pair('*', Tok::Pow, Tok::Mul);
      case '/':
        return pair('/', Tok::FloorDiv, Tok::Div);
      case '=':
        return pair('=', Tok::Eq, Tok::Assign);
      case '>':
        return pair('=', Tok::Ge, Tok::Gt);
      case '<':
        return pair('=', Tok::Le, Tok::Lt);
      case '!':
        length = second == '=' ? 2 : 0;
        return Tok::Ne;
      case '+':
        return Tok::Add;
      case '-':
        return Tok::Sub;
      case '%':
        return Tok::Mod;
      case '~':
        return Tok::Tilde;
      case '[':
        return Tok::LBracket;
      case ']':
        return Tok::RBracket;
      case '(':
        return Tok::LParen;
      case ')':
        return Tok::RParen;
      case '{':
        return Tok::LBrace;
      case '}':
        return Tok::RBrace;
      case '.':
        return Tok::Dot;
      case ':':
        return Tok::Colon;
      case '|':
        return Tok::Pipe;
      case ',':
        return Tok::Comma;
      case ';':
        return Tok::Semicolon;
      default:
        length = 0;
        return Tok::Eof;
    }
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
  bool line_starting_ = true;
  std::vector<char> balance_;
  std::vector<Token> out_;
};

}  // namespace

std::string normalizeSource(std::string_view source) {
  std::string out;
  out.reserve(source.size());
  // Copies the runs between carriage returns whole (templates rarely have any).
  size_t from = 0;
  for (size_t cr = source.find('\r'); cr != std::string_view::npos; cr = source.find('\r', from)) {
    out.append(source.substr(from, cr - from));
    out.push_back('\n');
    from = cr + 1 < source.size() && source[cr + 1] == '\n' ? cr + 2 : cr + 1;
  }
  out.append(source.substr(from));
  if (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

std::optional<std::string_view> normalizedInPlace(std::string_view source) {
  if (source.find('\r') != std::string_view::npos) return std::nullopt;
  if (!source.empty() && source.back() == '\n') source.remove_suffix(1);
  return source;
}

std::vector<Token> tokenize(std::string_view source, const LexerOptions& options) {
  return Lexer(source, options).run();
}

std::string_view describe(Tok kind) {
  switch (kind) {
    case Tok::Data:
      return "template data";
    case Tok::VariableBegin:
      return "{{";
    case Tok::VariableEnd:
      return "}}";
    case Tok::BlockBegin:
      return "{%";
    case Tok::BlockEnd:
      return "%}";
    case Tok::Name:
      return "name";
    case Tok::String:
      return "string";
    case Tok::Integer:
      return "integer";
    case Tok::Float:
      return "float";
    case Tok::Eof:
      return "end of template";
    case Tok::Add:
      return "+";
    case Tok::Sub:
      return "-";
    case Tok::Mul:
      return "*";
    case Tok::Div:
      return "/";
    case Tok::FloorDiv:
      return "//";
    case Tok::Mod:
      return "%";
    case Tok::Pow:
      return "**";
    case Tok::Tilde:
      return "~";
    case Tok::LBracket:
      return "[";
    case Tok::RBracket:
      return "]";
    case Tok::LParen:
      return "(";
    case Tok::RParen:
      return ")";
    case Tok::LBrace:
      return "{";
    case Tok::RBrace:
      return "}";
    case Tok::Eq:
      return "==";
    case Tok::Ne:
      return "!=";
    case Tok::Gt:
      return ">";
    case Tok::Ge:
      return ">=";
    case Tok::Lt:
      return "<";
    case Tok::Le:
      return "<=";
    case Tok::Assign:
      return "=";
    case Tok::Dot:
      return ".";
    case Tok::Colon:
      return ":";
    case Tok::Pipe:
      return "|";
    case Tok::Comma:
      return ",";
    case Tok::Semicolon:
      return ";";
  }
  return "token";
}

}  // namespace smachac::tmpl
