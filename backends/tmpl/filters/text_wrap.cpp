// textwrap.wrap and the tojson serialisation (see text_wrap.h).
#include "backends/tmpl/filters/text_wrap.h"

#include <algorithm>
#include <cmath>

#include "backends/tmpl/error.h"
#include "backends/tmpl/values/string_ops.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

using Chars = std::u32string;

bool isWrapSpace(char32_t c) {
  return c == '\t' || c == '\n' || c == 0x0B || c == 0x0C || c == '\r' || c == ' ';
}
bool isWordChar(char32_t c) { return c == '_' || unicode::isAlnum(c); }
bool isLetter(char32_t c) { return isWordChar(c) && !(c >= '0' && c <= '9'); }
bool isWordPunct(char32_t c) {
  return isWordChar(c) || c == '!' || c == '"' || c == '\'' || c == '&' || c == '.' || c == ',' ||
         c == '?';
}

class Splitter {
 public:
  Splitter(const Chars& s, bool hyphens) : s_(s), hyphens_(hyphens) {}

  std::vector<Chars> split() {
    std::vector<Chars> chunks;
    size_t i = 0;
    while (i < s_.size()) {
      size_t end = chunkEnd(i);
      chunks.push_back(s_.substr(i, end - i));
      i = end;
    }
    return chunks;
  }

 private:
  char32_t at(size_t i) const { return i < s_.size() ? s_[i] : 0; }

  size_t chunkEnd(size_t i) const {
    if (isWrapSpace(s_[i])) {
      while (i < s_.size() && isWrapSpace(s_[i])) ++i;
      return i;
    }
    if (!hyphens_) {
      while (i < s_.size() && !isWrapSpace(s_[i])) ++i;
      return i;
    }
    if (size_t dash = emDash(i)) return dash;
    for (size_t j = i + 1;; ++j) {  // lazily grow the word until one of the endings applies
      if (j > s_.size()) return s_.size();
      if (j == s_.size() || isWrapSpace(s_[j])) return j;
      if (s_[j] == '-' && hyphenBreak(j)) return j + 1;
      if (isWordPunct(s_[j - 1]) && dashes(j) >= 2 && isWordChar(at(j + dashes(j)))) return j;
      if (isWrapSpace(s_[j])) return j;
    }
  }

  size_t dashes(size_t i) const {
    size_t n = 0;
    while (at(i + n) == '-') ++n;
    return n;
  }

  // `--+` after a word-punctuation character and before a word character.
  size_t emDash(size_t i) const {
    size_t n = dashes(i);
    if (i == 0 || n < 2 || !isWordPunct(s_[i - 1]) || !isWordChar(at(i + n))) return 0;
    return i + n;
  }

  // A hyphen at j ends a chunk inside a hyphenated word.
  bool hyphenBreak(size_t j) const {
    bool behind = (j >= 2 && isLetter(s_[j - 2]) && isLetter(s_[j - 1])) ||
                  (j >= 3 && isLetter(s_[j - 3]) && s_[j - 2] == '-' && isLetter(s_[j - 1]));
    if (!behind) return false;
    size_t k = j + 1;
    if (!isLetter(at(k))) return false;
    if (at(k + 1) == '-') ++k;
    return isLetter(at(k + 1));
  }

  const Chars& s_;
  bool hyphens_;
};

bool blank(const Chars& c) {
  for (char32_t x : c) {
    if (!unicode::isSpace(x)) return false;
  }
  return true;
}

std::string encode(const Chars& c) {
  std::string out;
  for (char32_t x : c) unicode::encode(out, x);
  return out;
}

void handleLongWord(std::vector<Chars>& reversed, std::vector<Chars>& line, size_t line_len,
                    size_t width, bool break_long, bool hyphens) {
  size_t space_left = width < 1 ? 1 : width - line_len;
  if (break_long) {
    size_t end = space_left;
    Chars& chunk = reversed.back();
    if (hyphens && chunk.size() > space_left) {
      size_t hyphen = chunk.rfind('-', space_left == 0 ? 0 : space_left - 1);
      if (hyphen != Chars::npos && hyphen < space_left && hyphen > 0 &&
          chunk.substr(0, hyphen).find_first_not_of(U'-') != Chars::npos) {
        end = hyphen + 1;
      }
    }
    line.push_back(chunk.substr(0, end));
    chunk = chunk.substr(std::min(end, chunk.size()));
  } else if (line.empty()) {
    line.push_back(reversed.back());
    reversed.pop_back();
  }
}

}  // namespace

std::vector<std::string> wrapText(std::string_view text, int64_t width, bool break_long_words,
                                  bool break_on_hyphens) {
  if (width <= 0) fail("invalid width " + std::to_string(width) + " (must be > 0)");
  Chars chars;
  for (size_t pos = 0; pos < text.size();) chars.push_back(unicode::decode(text, pos));
  std::vector<Chars> reversed = Splitter(chars, break_on_hyphens).split();
  std::reverse(reversed.begin(), reversed.end());
  std::vector<std::string> lines;
  auto w = static_cast<size_t>(width);
  while (!reversed.empty()) {
    std::vector<Chars> line;
    size_t line_len = 0;
    if (!lines.empty() && blank(reversed.back())) reversed.pop_back();
    while (!reversed.empty() && line_len + reversed.back().size() <= w) {
      line_len += reversed.back().size();
      line.push_back(std::move(reversed.back()));
      reversed.pop_back();
    }
    if (!reversed.empty() && reversed.back().size() > w) {
      handleLongWord(reversed, line, line_len, w, break_long_words, break_on_hyphens);
    }
    if (!line.empty() && blank(line.back())) line.pop_back();
    if (!line.empty()) {
      std::string joined;
      for (const Chars& c : line) joined += encode(c);
      lines.push_back(std::move(joined));
    }
  }
  return lines;
}

namespace {

void jsonString(std::string& out, std::string_view s) {
  out.push_back('"');
  for (size_t pos = 0; pos < s.size();) {
    char32_t c = unicode::decode(s, pos);
    char buf[16];
    switch (c) {
      case '"':
        out += "\\\"";
        continue;
      case '\\':
        out += "\\\\";
        continue;
      case '\n':
        out += "\\n";
        continue;
      case '\r':
        out += "\\r";
        continue;
      case '\t':
        out += "\\t";
        continue;
      case '\b':
        out += "\\b";
        continue;
      case '\f':
        out += "\\f";
        continue;
      default:
        break;
    }
    if (c >= 0x20 && c < 0x7F) {
      out.push_back(static_cast<char>(c));
    } else if (c < 0x10000) {
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
      out += buf;
    } else {
      char32_t v = c - 0x10000;
      std::snprintf(buf, sizeof buf, "\\u%04x\\u%04x", static_cast<unsigned>(0xD800 | (v >> 10)),
                    static_cast<unsigned>(0xDC00 | (v & 0x3FF)));
      out += buf;
    }
  }
  out.push_back('"');
}

void jsonFloat(std::string& out, double d) {
  if (std::isnan(d)) {
    out += "NaN";
  } else if (std::isinf(d)) {
    out += d < 0 ? "-Infinity" : "Infinity";
  } else {
    appendFloatRepr(out, d);
  }
}

std::string jsonKey(const Value& key) {
  std::string out;
  switch (key.kind()) {
    case Kind::String:
      return key.s();
    case Kind::Bool:
      return key.b() ? "true" : "false";
    case Kind::None:
      return "null";
    case Kind::Int:
      appendInt(out, key.i());
      return out;
    case Kind::Float:
      jsonFloat(out, key.f());
      return out;
    default:
      fail("keys must be str, int, float, bool or None, not `" + std::string(typeName(key)) + "`");
  }
}

void jsonValue(std::string& out, const Value& v, int64_t indent, int64_t level);

void newline(std::string& out, int64_t indent, int64_t level) {
  if (indent < 0) return;
  out.push_back('\n');
  checkSize(out.size() + static_cast<size_t>(indent * level), "string");
  out.append(static_cast<size_t>(indent * level), ' ');
}

void jsonContainer(std::string& out, const Value& v, int64_t indent, int64_t level) {
  DepthGuard guard;
  bool dict = v.isDict();
  std::vector<Value> keys;
  if (dict) {
    for (const auto& entry : v.dict().entries()) keys.push_back(entry.first);
    keys = sortValues(std::move(keys), false);
  }
  size_t n = dict ? keys.size() : v.list().items().size();
  out.push_back(dict ? '{' : '[');
  if (n == 0) {
    out.push_back(dict ? '}' : ']');
    return;
  }
  for (size_t i = 0; i < n; ++i) {
    if (i > 0) out += indent >= 0 ? "," : ", ";
    newline(out, indent, level + 1);
    if (dict) {
      jsonString(out, jsonKey(keys[i]));
      out += ": ";
      jsonValue(out, *v.dict().find(keys[i]), indent, level + 1);
    } else {
      jsonValue(out, v.list().items()[i], indent, level + 1);
    }
  }
  newline(out, indent, level);
  out.push_back(dict ? '}' : ']');
}

void jsonValue(std::string& out, const Value& v, int64_t indent, int64_t level) {
  switch (v.kind()) {
    case Kind::None:
      out += "null";
      return;
    case Kind::Bool:
      out += v.b() ? "true" : "false";
      return;
    case Kind::Int:
      appendInt(out, v.i());
      return;
    case Kind::Float:
      jsonFloat(out, v.f());
      return;
    case Kind::String:
      jsonString(out, v.s());
      return;
    case Kind::List:
    case Kind::Tuple:
    case Kind::Dict:
      jsonContainer(out, v, indent, level);
      return;
    default:
      fail("object of type `" + std::string(typeName(v)) + "` is not JSON serializable");
  }
}

}  // namespace

std::string toJson(const Value& value, int64_t indent) {
  std::string json;
  jsonValue(json, value, indent, 0);
  std::string out;
  for (char c : json) {
    switch (c) {
      case '<':
        out += "\\u003c";
        break;
      case '>':
        out += "\\u003e";
        break;
      case '&':
        out += "\\u0026";
        break;
      case '\'':
        out += "\\u0027";
        break;
      default:
        out.push_back(c);
    }
  }
  return out;
}

}  // namespace smachac::tmpl
