// Decoding of string literals in templates, like Python's unicode-escape codec as Jinja2
// applies it: \\ \' \" \a \b \f \n \r \t \v, octal, \xhh, \uhhhh, \Uhhhhhhhh; unknown
// escapes are kept as written.
#include <cstdio>

#include "backends/tmpl/lexer/lexer.h"
#include "backends/tmpl/parser/parser.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

void appendEscapeOf(std::string& out, char32_t cp) {
  char buf[16];
  if (cp <= 0xFF) {
    std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(cp));
  } else if (cp <= 0xFFFF) {
    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(cp));
  } else {
    std::snprintf(buf, sizeof buf, "\\U%08x", static_cast<unsigned>(cp));
  }
  out += buf;
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(c | 0x20);
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

std::string unescapeString(std::string_view body, uint32_t pos) {
  std::string out;
  out.reserve(body.size());
  for (size_t i = 0; i < body.size();) {
    char c = body[i];
    if (c != '\\') {
      out.push_back(c);
      ++i;
      continue;
    }
    if (i + 1 >= body.size()) throw SyntaxFault{pos, "`\\` at end of string"};
    char e = body[i + 1];
    i += 2;
    switch (e) {
      case '\n':
        break;
      case '\\':
        out.push_back('\\');
        break;
      case '\'':
        out.push_back('\'');
        break;
      case '"':
        out.push_back('"');
        break;
      case 'a':
        out.push_back('\a');
        break;
      case 'b':
        out.push_back('\b');
        break;
      case 'f':
        out.push_back('\f');
        break;
      case 'n':
        out.push_back('\n');
        break;
      case 'r':
        out.push_back('\r');
        break;
      case 't':
        out.push_back('\t');
        break;
      case 'v':
        out.push_back('\v');
        break;
      case 'x':
      case 'u':
      case 'U': {
        size_t n = e == 'x' ? 2 : e == 'u' ? 4 : 8;
        char32_t cp = 0;
        for (size_t k = 0; k < n; ++k) {
          int d = i + k < body.size() ? hexDigit(body[i + k]) : -1;
          if (d < 0) {
            throw SyntaxFault{pos, std::string("truncated \\") + e + " escape in string"};
          }
          cp = cp * 16 + static_cast<char32_t>(d);
        }
        if (cp > 0x10FFFF) throw SyntaxFault{pos, "illegal unicode character in string"};
        i += n;
        unicode::encode(out, cp);
        break;
      }
      case 'N':
        throw SyntaxFault{pos, "`\\N{...}` escapes are not supported"};
      default:
        if (e >= '0' && e <= '7') {
          char32_t cp = static_cast<char32_t>(e - '0');
          for (int k = 0; k < 2 && i < body.size() && body[i] >= '0' && body[i] <= '7'; ++k) {
            cp = cp * 8 + static_cast<char32_t>(body[i++] - '0');
          }
          unicode::encode(out, cp);
        } else if (static_cast<unsigned char>(e) >= 0x80) {
          // Python escapes non-ASCII characters before decoding, so `\é` reads as `\xe9`.
          size_t p = i - 1;
          appendEscapeOf(out, unicode::decode(body, p));
          i = p;
        } else {
          out.push_back('\\');
          out.push_back(e);
        }
    }
  }
  return out;
}

}  // namespace smachac::tmpl
