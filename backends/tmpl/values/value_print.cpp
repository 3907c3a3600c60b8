// str() and repr() of values, following CPython's formatting rules.
#include "backends/tmpl/values/value_print.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "backends/tmpl/values/value_ops.h"
#include "ir/support/python_float.h"
#include "ir/support/python_text.h"

namespace smachac::tmpl {
namespace {

// Containers being printed, to print `[...]` for self references like Python.
thread_local std::vector<const void*> printing;

class ReprEnter {
 public:
  explicit ReprEnter(const void* identity) {
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
  bool recursive_ = false;
};

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

void appendFloatRepr(std::string& out, double d) { out += pythonFloatRepr(d); }

void appendStr(std::string& out, const Value& v) {
  switch (v.kind()) {
    case Kind::Undefined:
      return;
    case Kind::String:
      out += v.s();
      return;
    case Kind::Object:
      v.object()->str(out);
      return;
    default:
      appendRepr(out, v);
  }
}

namespace {

// Whether repr() writes `text` between single quotes as it is: printable ASCII without a
// quote or backslash (the names and keys SMACHA's `pyrepr` prints), checked 8 bytes a step.
bool isPlainReprText(std::string_view text) {
  constexpr uint64_t kOnes = 0x0101010101010101ull;
  constexpr uint64_t kHigh = 0x8080808080808080ull;
  auto has_byte = [](uint64_t word, unsigned char byte) {
    uint64_t x = word ^ (kOnes * byte);
    return ((x - kOnes) & ~x & kHigh) != 0;
  };
  size_t i = 0;
  for (; i + 8 <= text.size(); i += 8) {
    uint64_t word;
    std::memcpy(&word, text.data() + i, sizeof word);
    uint64_t below_space = (word - kOnes * 0x20) & ~word & kHigh;
    uint64_t from_delete = ((word + kOnes) | word) & kHigh;  // 0x7F and above
    if (below_space || from_delete || has_byte(word, '\\') || has_byte(word, '\'')) return false;
  }
  for (; i < text.size(); ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c >= 0x7F || c == '\\' || c == '\'') return false;
  }
  return true;
}

}  // namespace

void appendStringRepr(std::string& out, std::string_view text) {
  if (!isPlainReprText(text)) return appendPythonStringRepr(out, text);
  out.reserve(out.size() + text.size() + 2);
  out += '\'';
  out.append(text);
  out += '\'';
}

void appendRepr(std::string& out, const Value& v) {
  switch (v.kind()) {
    case Kind::Undefined:
      out += "Undefined";
      return;
    case Kind::None:
      out += "None";
      return;
    case Kind::Bool:
      out += v.b() ? "True" : "False";
      return;
    case Kind::Int:
      appendInt(out, v.i());
      return;
    case Kind::Float:
      appendFloatRepr(out, v.f());
      return;
    case Kind::String:
      if (v.isMarkup()) {
        out += "Markup(";
        appendPythonStringRepr(out, v.s());
        out += ")";
        return;
      }
      appendStringRepr(out, v.s());
      return;
    case Kind::List:
    case Kind::Tuple:
      appendSequence(out, v);
      return;
    case Kind::Dict:
      appendDict(out, v);
      return;
    case Kind::Object:
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
