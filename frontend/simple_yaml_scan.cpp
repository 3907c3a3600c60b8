// One-line scalars of the simple YAML reader, scanned as yaml-cpp scans them.
#include "frontend/simple_yaml_scan.h"

namespace smachac::frontend {
namespace {

bool isAlnum(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

bool isNonAscii(char c) { return static_cast<unsigned char>(c) >= 0x80; }

/// `---` or `...` followed by a blank at the start of a line: a document marker.
bool atDocumentMarker(const YamlCursor& c) {
  if (c.column() != 0) return false;
  char m = c.peek();
  if ((m != '-' && m != '.') || c.peek(1) != m || c.peek(2) != m) return false;
  char after = c.peek(3);
  return after == ' ' || after == '\n' || after == '\0';
}

/// Unescapes the escape sequence after a backslash; false for any the reader does not handle.
bool unescape(char code, std::string& out) {
  constexpr std::string_view kCodes = "\\\"/ntr";
  constexpr std::string_view kBytes = "\\\"/\n\t\r";
  size_t i = kCodes.find(code);
  if (i == std::string_view::npos) return false;
  out += kBytes[i];
  return true;
}

bool scanDoubleQuoted(YamlCursor& c, YamlScalar& out) {
  size_t start = ++c.pos;
  bool escaped = false;
  while (true) {
    if (c.atLineEnd()) return false;
    char ch = c.text[c.pos];
    if (ch == '"') break;
    if (ch == '\\') {
      if (!escaped) out.owned.assign(c.text.substr(start, c.pos - start));
      escaped = true;
      if (!unescape(c.peek(1), out.owned)) return false;
      c.pos += 2;
      continue;
    }
    if (escaped) out.owned += ch;
    ++c.pos;
  }
  out.text = escaped ? std::string_view(out.owned) : c.text.substr(start, c.pos - start);
  ++c.pos;
  return true;
}

bool scanSingleQuoted(YamlCursor& c, YamlScalar& out) {
  size_t start = ++c.pos;
  bool escaped = false;
  while (true) {
    if (c.atLineEnd()) return false;
    char ch = c.text[c.pos];
    if (ch == '\'' && c.peek(1) != '\'') break;
    if (ch == '\'') {
      if (!escaped) out.owned.assign(c.text.substr(start, c.pos - start));
      escaped = true;
      out.owned += '\'';
      c.pos += 2;
      continue;
    }
    if (escaped) out.owned += ch;
    ++c.pos;
  }
  out.text = escaped ? std::string_view(out.owned) : c.text.substr(start, c.pos - start);
  ++c.pos;
  return true;
}

/// Where a block plain scalar ends: `: `, ` #` or the line end.
bool endsBlockPlain(const YamlCursor& c) {
  char ch = c.peek();
  if (ch == ':') {
    char next = c.peek(1);
    return next == ' ' || next == '\n' || next == '\0';
  }
  return ch == '\n' || ch == '\0' || (ch == ' ' && c.peek(1) == '#');
}

}  // namespace

void YamlCursor::nextLine() {
  while (pos < text.size() && text[pos] != '\n') ++pos;
  if (pos == text.size()) return;  // the last line has no line break
  ++pos;
  ++line;
  line_start = pos;
}

bool hasOnlySimpleBytes(std::string_view text) {
  for (size_t i = 0; i < text.size(); ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) continue;
    if (c == '\n') continue;
    if (c < 0x80) return false;  // tab, carriage return, other control bytes, DEL
    std::string_view rest = text.substr(i);
    if (rest.starts_with("\xEF\xBB\xBF") || rest.starts_with("\xC2\x85") ||
        rest.starts_with("\xE2\x80\xA8") || rest.starts_with("\xE2\x80\xA9")) {
      return false;  // byte order mark, NEL, line and paragraph separators
    }
  }
  return true;
}

bool startsSimplePlain(const YamlCursor& c) {
  char ch = c.peek();
  if (isAlnum(ch) || isNonAscii(ch)) return true;
  if (ch == '-') return isAlnum(c.peek(1)) || c.peek(1) == '.';
  if (ch == '.') return !atDocumentMarker(c);
  return ch == '_' || ch == '/' || ch == '$' || ch == '(' || ch == '~' || ch == '+';
}

bool scanPlain(YamlCursor& c, YamlContext context, YamlScalar& out) {
  out.mark = c.mark();
  out.quoted = false;
  size_t start = c.pos;
  size_t end = c.pos;  // one past the last non-space byte
  while (true) {
    if (context == YamlContext::Block) {
      if (endsBlockPlain(c)) break;
    } else {
      char ch = c.peek();
      if (ch == ',' || ch == '[' || ch == ']' || ch == '{' || ch == '}') break;
      if (ch == ':' && c.peek(1) == ' ') break;
      if (ch == ':' || ch == '#' || ch == '?' || ch == '"' || ch == '\'' || c.atLineEnd()) {
        return false;
      }
    }
    if (c.text[c.pos] != ' ') end = c.pos + 1;
    ++c.pos;
  }
  out.text = c.text.substr(start, end - start);
  return true;
}

bool scanQuoted(YamlCursor& c, YamlScalar& out) {
  out.mark = c.mark();
  out.quoted = true;
  return c.peek() == '"' ? scanDoubleQuoted(c, out) : scanSingleQuoted(c, out);
}

bool isNullPlain(std::string_view text) {
  return text == "~" || text == "null" || text == "Null" || text == "NULL";
}

}  // namespace smachac::frontend
