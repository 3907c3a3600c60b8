// str() and repr() of values, following CPython's formatting rules.
#include "backends/tmpl/values/value_print.h"

#include <charconv>
#include <cmath>
#include <cstdio>
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
      appendPythonStringRepr(out, v.s());
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
