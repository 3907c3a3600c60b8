// str() and repr() of values, following CPython's formatting rules.
#include "backends/tmpl/value_print.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

#include "backends/tmpl/unicode.h"
#include "backends/tmpl/value_ops.h"

namespace smachac::tmpl {
namespace {

// Containers being printed, to print `[...]` for self references like Python.
thread_local std::vector<const void*> printing;

class ReprEnter {
 public:
  explicit ReprEnter(const void* identity) : identity_(identity) {
    for (const void* p : printing) recursive_ = recursive_ || p == identity;
    if (!recursive_) printing.push_back(identity);
  }
  ~ReprEnter() {
    if (!recursive_) printing.pop_back();
  }
  ReprEnter(const ReprEnter&) = delete;
  ReprEnter& operator=(const ReprEnter&) = delete;
  bool recursive() const { return recursive_; }

 private:
  const void* identity_;
  bool recursive_ = false;
};

void appendHex(std::string& out, char prefix, uint32_t cp, int digits) {
  static const char* kHex = "0123456789abcdef";
  out.push_back('\\');
  out.push_back(prefix);
  for (int shift = (digits - 1) * 4; shift >= 0; shift -= 4)
    out.push_back(kHex[(cp >> shift) & 15]);
}

void appendEscapedChar(std::string& out, char32_t cp, char quote) {
  if (cp == static_cast<char32_t>(quote) || cp == '\\') {
    out.push_back('\\');
    out.push_back(static_cast<char>(cp));
  } else if (cp == '\t') {
    out += "\\t";
  } else if (cp == '\n') {
    out += "\\n";
  } else if (cp == '\r') {
    out += "\\r";
  } else if (unicode::isPrintable(cp)) {
    unicode::encode(out, cp);
  } else if (cp <= 0xFF) {
    appendHex(out, 'x', cp, 2);
  } else if (cp <= 0xFFFF) {
    appendHex(out, 'u', cp, 4);
  } else {
    appendHex(out, 'U', cp, 8);
  }
}

void appendSequence(std::string& out, const Value& v) {
  bool tuple = v.isTuple();
  ReprEnter enter(v.identity());
  if (enter.recursive()) {
    out += tuple ? "(...)" : "[...]";
    return;
  }
  DepthGuard guard;
  const auto& items = v.list().items();
  out.push_back(tuple ? '(' : '[');
  for (size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += ", ";
    appendRepr(out, items[i]);
  }
  if (tuple && items.size() == 1) out.push_back(',');
  out.push_back(tuple ? ')' : ']');
}

void appendDict(std::string& out, const Value& v) {
  ReprEnter enter(v.identity());
  if (enter.recursive()) {
    out += "{...}";
    return;
  }
  DepthGuard guard;
  out.push_back('{');
  bool first = true;
  for (const auto& [key, value] : v.dict().entries()) {
    if (!first) out += ", ";
    first = false;
    appendRepr(out, key);
    out += ": ";
    appendRepr(out, value);
  }
  out.push_back('}');
}

}  // namespace

void appendInt(std::string& out, int64_t i) {
  char buf[24];
  auto result = std::to_chars(buf, buf + sizeof buf, i);
  out.append(buf, result.ptr);
}

void appendFloatRepr(std::string& out, double d) {
  if (std::isnan(d)) {
    out += "nan";
    return;
  }
  if (std::isinf(d)) {
    out += d < 0 ? "-inf" : "inf";
    return;
  }
  char buf[40];
  auto result = std::to_chars(buf, buf + sizeof buf, d, std::chars_format::scientific);
  std::string_view sci(buf, static_cast<size_t>(result.ptr - buf));
  bool negative = sci.front() == '-';
  if (negative) sci.remove_prefix(1);
  size_t e = sci.find('e');
  std::string digits;
  for (char c : sci.substr(0, e)) {
    if (c != '.') digits.push_back(c);
  }
  int exponent = std::stoi(std::string(sci.substr(e + 1)));
  int decpt = exponent + 1;
  if (negative) out.push_back('-');
  if (decpt > -4 && decpt <= 16) {
    if (decpt <= 0) {
      out += "0.";
      out.append(static_cast<size_t>(-decpt), '0');
      out += digits;
    } else if (static_cast<size_t>(decpt) >= digits.size()) {
      out += digits;
      out.append(static_cast<size_t>(decpt) - digits.size(), '0');
      out += ".0";
    } else {
      out += digits.substr(0, static_cast<size_t>(decpt));
      out.push_back('.');
      out += digits.substr(static_cast<size_t>(decpt));
    }
    return;
  }
  out.push_back(digits[0]);
  if (digits.size() > 1) {
    out.push_back('.');
    out += digits.substr(1);
  }
  char expBuf[16];
  std::snprintf(expBuf, sizeof expBuf, "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
  out += expBuf;
}

void appendQuoted(std::string& out, std::string_view s) {
  bool hasSingle = s.find('\'') != std::string_view::npos;
  bool hasDouble = s.find('"') != std::string_view::npos;
  char quote = hasSingle && !hasDouble ? '"' : '\'';
  out.push_back(quote);
  for (size_t pos = 0; pos < s.size();) {
    unsigned char c = static_cast<unsigned char>(s[pos]);
    if (c >= 0x20 && c < 0x7F && c != '\\' && c != static_cast<unsigned char>(quote)) {
      out.push_back(static_cast<char>(c));
      ++pos;
      continue;
    }
    appendEscapedChar(out, unicode::decode(s, pos), quote);
  }
  out.push_back(quote);
}

void appendStr(std::string& out, const Value& v) {
  switch (v.kind()) {
    case Kind::kUndefined:
      return;
    case Kind::kString:
      out += v.s();
      return;
    case Kind::kObject:
      v.object()->str(out);
      return;
    default:
      appendRepr(out, v);
  }
}

void appendRepr(std::string& out, const Value& v) {
  switch (v.kind()) {
    case Kind::kUndefined:
      out += "Undefined";
      return;
    case Kind::kNone:
      out += "None";
      return;
    case Kind::kBool:
      out += v.b() ? "True" : "False";
      return;
    case Kind::kInt:
      appendInt(out, v.i());
      return;
    case Kind::kFloat:
      appendFloatRepr(out, v.f());
      return;
    case Kind::kString:
      if (v.isMarkup()) {
        out += "Markup(";
        appendQuoted(out, v.s());
        out += ")";
        return;
      }
      appendQuoted(out, v.s());
      return;
    case Kind::kList:
    case Kind::kTuple:
      appendSequence(out, v);
      return;
    case Kind::kDict:
      appendDict(out, v);
      return;
    case Kind::kObject:
      v.object()->repr(out);
      return;
  }
}

std::string str(const Value& v) {
  if (v.isString()) return v.s();
  std::string out;
  appendStr(out, v);
  return out;
}

std::string repr(const Value& v) {
  std::string out;
  appendRepr(out, v);
  return out;
}

std::string htmlEscape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '\'':
        out += "&#39;";
        break;
      case '"':
        out += "&#34;";
        break;
      default:
        out.push_back(c);
    }
  }
  return out;
}

}  // namespace smachac::tmpl
