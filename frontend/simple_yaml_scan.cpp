// One-line scalars of the simple YAML reader, scanned as yaml-cpp scans them.
#include "frontend/simple_yaml_scan.h"

namespace smachac::frontend {
namespace {

bool isAlnum(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

bool isNonAscii(char c) { return static_cast<unsigned char>(c) >= 0x80; }

/// Bytes checked at once by hasOnlySimpleBytes: the branch-free loop over a chunk vectorises.
constexpr size_t kSimpleChunk = 64;

bool isPrintableOrNewline(unsigned char c) { return (c >= 0x20 && c < 0x7F) || c == '\n'; }

/// True when the kSimpleChunk bytes at `chunk` are all printable ASCII or line feeds (no early
/// exit, a fixed count: the compiler vectorises it).
bool isPlainAsciiChunk(const char* chunk) {
  unsigned char odd = 0;
  for (size_t i = 0; i < kSimpleChunk; ++i) {
    auto c = static_cast<unsigned char>(chunk[i]);
    odd |= static_cast<unsigned char>(static_cast<unsigned char>(c - 0x20) > 0x5E) &
           static_cast<unsigned char>(c != '\n');
  }
  return odd == 0;
}

/// Whether the odd byte at `i` may stay: a non-ASCII byte that does not start a byte order
/// mark, NEL or a line or paragraph separator.
bool simpleAt(std::string_view text, size_t i) {
  if (static_cast<unsigned char>(text[i]) < 0x80) return false;  // control bytes, DEL
  std::string_view rest = text.substr(i);
  return !(rest.starts_with("\xEF\xBB\xBF") || rest.starts_with("\xC2\x85") ||
           rest.starts_with("\xE2\x80\xA8") || rest.starts_with("\xE2\x80\xA9"));
}

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

/// The bytes at which the scan of a plain scalar stops to look (one table lookup for every
/// other byte, which is simply part of the scalar).
struct PlainStops {
  bool block[256] = {};
  bool flow[256] = {};
};

constexpr PlainStops kPlainStops = [] {
  PlainStops stops;
  for (char c : std::string_view(" :\n")) stops.block[static_cast<unsigned char>(c)] = true;
  for (char c : std::string_view(" :\n,[]{}#?\"'"))
    stops.flow[static_cast<unsigned char>(c)] = true;
  return stops;
}();

/// Moves past a block plain scalar, up to `: `, ` #` or the line end; returns one past its
/// last non-space byte.
size_t skipBlockPlain(YamlCursor& c) {
  std::string_view t = c.text;
  size_t i = c.pos;
  size_t end = c.pos;
  for (; i < t.size(); ++i) {
    char ch = t[i];
    if (!kPlainStops.block[static_cast<unsigned char>(ch)]) {
      end = i + 1;
      continue;
    }
    if (ch == '\n') break;
    char next = i + 1 < t.size() ? t[i + 1] : '\0';
    if (ch == ' ') {
      if (next == '#') break;
      continue;
    }
    if (next == ' ' || next == '\n' || next == '\0') break;  // `:` and a blank
    end = i + 1;
  }
  c.pos = i;
  return end;
}

bool endsFlowPlain(char ch, char next) {
  return ch == ',' || ch == '[' || ch == ']' || ch == '{' || ch == '}' ||
         (ch == ':' && next == ' ');
}

/// Moves past a flow plain scalar, up to `,[]{}` or `: `; false at anything the reader leaves
/// to yaml-cpp (`:`, `#`, `?`, a quote, the line end). `end` is one past its last non-space.
bool skipFlowPlain(YamlCursor& c, size_t& end) {
  std::string_view t = c.text;
  for (size_t i = c.pos; i < t.size(); ++i) {
    char ch = t[i];
    if (!kPlainStops.flow[static_cast<unsigned char>(ch)]) {
      end = i + 1;
      continue;
    }
    if (endsFlowPlain(ch, i + 1 < t.size() ? t[i + 1] : '\0')) {
      c.pos = i;
      return true;
    }
    if (ch == ':' || ch == '#' || ch == '?' || ch == '"' || ch == '\'' || ch == '\n') return false;
    if (ch != ' ') end = i + 1;
  }
  return false;
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
  for (size_t i = 0; i < text.size();) {
    if (text.size() - i >= kSimpleChunk && isPlainAsciiChunk(text.data() + i)) {
      i += kSimpleChunk;
      continue;
    }
    if (!isPrintableOrNewline(static_cast<unsigned char>(text[i])) && !simpleAt(text, i)) {
      return false;
    }
    ++i;
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
  size_t end = c.pos;
  if (context == YamlContext::Block) {
    end = skipBlockPlain(c);
  } else if (!skipFlowPlain(c, end)) {
    return false;
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
