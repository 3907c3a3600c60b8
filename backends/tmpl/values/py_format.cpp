// Python's printf-style (%) and str.format() formatting of values.
#include "backends/tmpl/values/py_format.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include "backends/tmpl/error.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

constexpr int kMaxWidth = 1000000;

struct Spec {
  char fill = ' ';
  char align = 0;  // < > ^ =
  char sign = '-';
  bool alternate = false;
  bool zero = false;
  int width = -1;
  char grouping = 0;
  int precision = -1;
  char type = 0;
};

std::string pad(std::string body, const Spec& spec, char default_align) {
  int len = static_cast<int>(unicode::length(body));
  if (spec.width <= len) return body;
  size_t missing = static_cast<size_t>(spec.width - len);
  char align = spec.align ? spec.align : default_align;
  std::string fill(1, spec.fill);
  auto repeat_fill = [&](size_t n) {
    std::string s;
    for (size_t i = 0; i < n; ++i) s += fill;
    return s;
  };
  if (align == '<') return body + repeat_fill(missing);
  if (align == '^') return repeat_fill(missing / 2) + body + repeat_fill(missing - missing / 2);
  if (align == '=') {
    size_t sign_len =
        (!body.empty() && (body[0] == '-' || body[0] == '+' || body[0] == ' ')) ? 1 : 0;
    if (body.size() > sign_len + 1 && body[sign_len] == '0' &&
        std::string_view("xXob").find(body[sign_len + 1]) != std::string_view::npos) {
      sign_len += 2;
    }
    return body.substr(0, sign_len) + repeat_fill(missing) + body.substr(sign_len);
  }
  return repeat_fill(missing) + body;
}

std::string group(std::string digits, char sep, size_t every) {
  std::string out;
  size_t n = digits.size();
  for (size_t i = 0; i < n; ++i) {
    if (i > 0 && (n - i) % every == 0) out.push_back(sep);
    out.push_back(digits[i]);
  }
  return out;
}

std::string signOf(bool negative, char sign) {
  if (negative) return "-";
  if (sign == '+') return "+";
  if (sign == ' ') return " ";
  return "";
}

std::string intDigits(int64_t v, char type) {
  uint64_t u = v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
  if (type == 'x' || type == 'X' || type == 'o' || type == 'b') {
    int base = type == 'o' ? 8 : type == 'b' ? 2 : 16;
    const char* digits = type == 'X' ? "0123456789ABCDEF" : "0123456789abcdef";
    std::string out;
    do {
      out.insert(out.begin(), digits[u % static_cast<uint64_t>(base)]);
      u /= static_cast<uint64_t>(base);
    } while (u);
    return out;
  }
  return std::to_string(u);
}

std::string formatInt(int64_t v, const Spec& spec) {
  char type = spec.type ? spec.type : 'd';
  if (type == 'n') type = 'd';
  if (type == 'c') {
    std::string s;
    unicode::encode(s, static_cast<char32_t>(v));
    return pad(s, spec, '<');
  }
  std::string digits = intDigits(v, type);
  if (spec.grouping) digits = group(digits, spec.grouping, type == 'd' ? 3 : 4);
  std::string prefix;
  if (spec.alternate && type != 'd') prefix = std::string("0") + (type == 'X' ? 'X' : type);
  std::string body = signOf(v < 0, spec.sign) + prefix + digits;
  if (spec.zero && !spec.align) {
    Spec zero_spec = spec;
    zero_spec.fill = '0';
    zero_spec.align = '=';
    return pad(body, zero_spec, '>');
  }
  return pad(body, spec, '>');
}

std::string cFormat(double d, char type, int precision, bool alternate) {
  char fmt[16];
  std::snprintf(fmt, sizeof fmt, "%%%s.%d%c", alternate ? "#" : "", precision, type);
  int n = std::snprintf(nullptr, 0, fmt, d);
  std::string out(static_cast<size_t>(n), '\0');
  std::snprintf(out.data(), out.size() + 1, fmt, d);
  return out;
}

std::string groupFloat(const std::string& s, char sep) {
  size_t end = s.find_first_not_of("0123456789");
  if (end == std::string::npos) end = s.size();
  return group(s.substr(0, end), sep, 3) + s.substr(end);
}

std::string formatFloat(double d, const Spec& spec) {
  char type = spec.type;
  std::string body;
  bool negative = std::signbit(d) && !std::isnan(d);
  double a = std::fabs(d);
  if (type == 0 && spec.precision < 0) {
    appendFloatRepr(body, a);
  } else if (type == 0) {
    body = cFormat(a, 'g', spec.precision == 0 ? 1 : spec.precision, spec.alternate);
    if (std::isfinite(a) && body.find_first_of(".e") == std::string::npos) body += ".0";
  } else if (type == '%') {
    body = cFormat(a * 100, 'f', spec.precision < 0 ? 6 : spec.precision, spec.alternate) + "%";
  } else {
    char t = type == 'n' ? 'g' : type;
    body = cFormat(a, t, spec.precision < 0 ? 6 : spec.precision, spec.alternate);
  }
  if (spec.grouping && std::isfinite(a)) body = groupFloat(body, spec.grouping);
  body = signOf(negative, spec.sign) + body;
  if (spec.zero && !spec.align && std::isfinite(a)) {
    Spec zero_spec = spec;
    zero_spec.fill = '0';
    zero_spec.align = '=';
    return pad(body, zero_spec, '>');
  }
  return pad(body, spec, '>');
}

int parseNumber(std::string_view s, size_t& i) {
  int64_t n = 0;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9') {
    n = n * 10 + (s[i++] - '0');
    if (n > kMaxWidth) fail("format width or precision too large");
  }
  return static_cast<int>(n);
}

Spec parseSpec(std::string_view s) {
  Spec spec;
  size_t i = 0;
  auto is_align = [](char c) { return c == '<' || c == '>' || c == '^' || c == '='; };
  if (s.size() >= 2 && is_align(s[1])) {
    spec.fill = s[0];
    spec.align = s[1];
    i = 2;
  } else if (!s.empty() && is_align(s[0])) {
    spec.align = s[0];
    i = 1;
  }
  if (i < s.size() && (s[i] == '+' || s[i] == '-' || s[i] == ' ')) spec.sign = s[i++];
  if (i < s.size() && s[i] == 'z') ++i;
  if (i < s.size() && s[i] == '#') {
    spec.alternate = true;
    ++i;
  }
  if (i < s.size() && s[i] == '0') {
    spec.zero = true;
    ++i;
  }
  if (i < s.size() && s[i] >= '0' && s[i] <= '9') spec.width = parseNumber(s, i);
  if (i < s.size() && (s[i] == ',' || s[i] == '_')) spec.grouping = s[i++];
  if (i < s.size() && s[i] == '.') {
    ++i;
    if (i >= s.size() || s[i] < '0' || s[i] > '9') fail("format specifier missing precision");
    spec.precision = parseNumber(s, i);
  }
  if (i < s.size()) spec.type = s[i++];
  if (i != s.size()) fail("invalid format specifier `" + std::string(s) + "`");
  return spec;
}

[[noreturn]] void unknownCode(char type, const Value& v) {
  fail("unknown format code `" + std::string(1, type) + "` for object of type `" +
       std::string(typeName(v)) + "`");
}

std::string formatValue(const Value& v, std::string_view spec_text) {
  if (spec_text.empty()) return str(v);
  Spec spec = parseSpec(spec_text);
  if (v.isInt() || v.isBool()) {
    if (spec.type && std::string_view("eEfFgG%").find(spec.type) != std::string_view::npos) {
      return formatFloat(static_cast<double>(v.integral()), spec);
    }
    if (spec.type && std::string_view("bcdoxXn").find(spec.type) == std::string_view::npos) {
      unknownCode(spec.type, v);
    }
    return formatInt(v.integral(), spec);
  }
  if (v.isFloat()) {
    if (spec.type && std::string_view("eEfFgGn%").find(spec.type) == std::string_view::npos) {
      unknownCode(spec.type, v);
    }
    return formatFloat(v.f(), spec);
  }
  if (v.isString()) {
    if (spec.type && spec.type != 's') unknownCode(spec.type, v);
    std::string s = v.s();
    if (spec.precision >= 0) {
      size_t pos = 0;
      for (int n = 0; n < spec.precision && pos < s.size(); ++n) unicode::decode(s, pos);
      s.resize(pos);
    }
    return pad(s, spec, '<');
  }
  fail("unsupported format string passed to `" + std::string(typeName(v)) + "`.__format__");
}

// --- printf-style ---------------------------------------------------------------------------

class PercentArgs {
 public:
  explicit PercentArgs(const Value& args) : args_(args) {
    if (args.isTuple()) items_ = &args.list().items();
  }
  Value next() {
    if (items_) {
      if (index_ >= items_->size()) fail("not enough arguments for format string");
      return (*items_)[index_++];
    }
    if (index_++ > 0) fail("not enough arguments for format string");
    return args_;
  }
  Value byKey(std::string_view key) const {
    if (!args_.isDict()) fail("format requires a mapping");
    const Value* v = args_.dict().findString(key);
    if (!v) fail("key `" + std::string(key) + "` not found in format mapping");
    return *v;
  }
  bool allUsed() const { return items_ ? index_ == items_->size() : index_ > 0 || args_.isDict(); }

 private:
  Value args_;
  const std::vector<Value>* items_ = nullptr;
  size_t index_ = 0;
};

double numberArg(const Value& v, char type) {
  if (v.isNumber()) return v.number();
  fail("%" + std::string(1, type) + " format: a real number is required, not `" +
       std::string(typeName(v)) + "`");
}

int64_t intArg(const Value& v, char type) {
  if (v.isInt() || v.isBool()) return v.integral();
  if (v.isFloat() && (type == 'd' || type == 'i' || type == 'u')) return floatToInt(v.f());
  fail("%" + std::string(1, type) + " format: an integer is required, not `" +
       std::string(typeName(v)) + "`");
}

std::string percentOne(const Value& arg, Spec spec, bool markup) {
  char type = spec.type;
  switch (type) {
    case 's':
    case 'r':
    case 'a': {
      std::string s = type == 's' ? str(arg) : repr(arg);
      if (markup && !arg.isMarkup()) s = htmlEscape(s);
      if (spec.precision >= 0) {
        size_t pos = 0;
        for (int n = 0; n < spec.precision && pos < s.size(); ++n) unicode::decode(s, pos);
        s.resize(pos);
      }
      spec.precision = -1;
      return pad(s, spec, '>');
    }
    case 'd':
    case 'i':
    case 'u': {
      spec.type = 'd';
      int64_t v = intArg(arg, type);
      if (spec.precision >= 0) {
        std::string digits = intDigits(v, 'd');
        if (static_cast<int>(digits.size()) < spec.precision) {
          digits.insert(0, static_cast<size_t>(spec.precision) - digits.size(), '0');
        }
        Spec p = spec;
        return pad(signOf(v < 0, spec.sign) + digits, p, '>');
      }
      return formatInt(v, spec);
    }
    case 'o':
    case 'x':
    case 'X':
      return formatInt(intArg(arg, type), spec);
    case 'c':
      if (arg.isString()) return pad(arg.s(), spec, '>');
      return formatInt(intArg(arg, type), spec);
    case 'e':
    case 'E':
    case 'f':
    case 'F':
    case 'g':
    case 'G': {
      if (spec.precision < 0) spec.precision = 6;
      return formatFloat(numberArg(arg, type), spec);
    }
    default:
      fail("unsupported format character `" + std::string(1, type) + "`");
  }
}

}  // namespace

Value percentFormat(const Value& fmt, const Value& args) {
  const std::string& f = fmt.s();
  PercentArgs source(args);
  std::string out;
  bool used_keys = false;
  for (size_t i = 0; i < f.size();) {
    if (f[i] != '%') {
      out.push_back(f[i++]);
      continue;
    }
    if (++i >= f.size()) fail("incomplete format");
    if (f[i] == '%') {
      out.push_back('%');
      ++i;
      continue;
    }
    std::optional<std::string> key;
    if (f[i] == '(') {
      size_t close = f.find(')', i);
      if (close == std::string::npos) fail("incomplete format key");
      key = f.substr(i + 1, close - i - 1);
      i = close + 1;
      used_keys = true;
    }
    Spec spec;
    spec.align = '>';
    for (; i < f.size() && std::string_view("#0- +").find(f[i]) != std::string_view::npos; ++i) {
      if (f[i] == '-') spec.align = '<';
      if (f[i] == '0') spec.zero = true;
      if (f[i] == '+' || f[i] == ' ') spec.sign = spec.sign == '+' ? '+' : f[i];
      if (f[i] == '#') spec.alternate = true;
    }
    if (spec.align == '<') spec.zero = false;
    if (i < f.size() && f[i] == '*') {
      spec.width = static_cast<int>(intArg(source.next(), '*'));
      ++i;
    } else {
      spec.width = parseNumber(f, i);
    }
    if (i < f.size() && f[i] == '.') {
      ++i;
      spec.precision = parseNumber(f, i);
    }
    while (i < f.size() && (f[i] == 'h' || f[i] == 'l' || f[i] == 'L')) ++i;
    if (i >= f.size()) fail("incomplete format");
    spec.type = f[i++];
    if (spec.zero) spec.align = 0;
    Value arg = key ? source.byKey(*key) : source.next();
    out += percentOne(arg, spec, fmt.isMarkup());
    checkSize(out.size(), "string");
  }
  if (!used_keys && !source.allUsed() && !args.isDict()) {
    fail("not all arguments converted during string formatting");
  }
  return Value::string(std::move(out), fmt.isMarkup());
}

Value braceFormat(const Value& fmt, const std::vector<Value>& args, const DictObject* kwargs) {
  const std::string& f = fmt.s();
  std::string out;
  size_t auto_index = 0;
  for (size_t i = 0; i < f.size();) {
    char c = f[i];
    if (c == '}') {
      if (i + 1 < f.size() && f[i + 1] == '}') {
        out.push_back('}');
        i += 2;
        continue;
      }
      fail("single `}` encountered in format string");
    }
    if (c != '{') {
      out.push_back(c);
      ++i;
      continue;
    }
    if (i + 1 < f.size() && f[i + 1] == '{') {
      out.push_back('{');
      i += 2;
      continue;
    }
    size_t close = f.find('}', i);
    if (close == std::string::npos) fail("single `{` encountered in format string");
    std::string_view field(f.data() + i + 1, close - i - 1);
    i = close + 1;
    std::string_view spec;
    if (size_t colon = field.find(':'); colon != std::string_view::npos) {
      spec = field.substr(colon + 1);
      field = field.substr(0, colon);
    }
    char conversion = 0;
    if (size_t bang = field.find('!'); bang != std::string_view::npos) {
      if (bang + 2 != field.size()) fail("invalid conversion in format string");
      conversion = field[bang + 1];
      field = field.substr(0, bang);
    }
    Value v;
    if (field.empty()) {
      if (auto_index >= args.size())
        fail("replacement index " + std::to_string(auto_index) + " out of range");
      v = args[auto_index++];
    } else if (field.find_first_not_of("0123456789") == std::string_view::npos) {
      size_t index = std::stoul(std::string(field));
      if (index >= args.size()) fail("replacement index " + std::string(field) + " out of range");
      v = args[index];
    } else {
      const Value* found = kwargs ? kwargs->findString(field) : nullptr;
      if (!found) fail("format key `" + std::string(field) + "` not found");
      v = *found;
    }
    if (conversion == 'r' || conversion == 'a') {
      v = Value::string(repr(v));
    } else if (conversion == 's') {
      v = Value::string(str(v));
    } else if (conversion != 0) {
      fail("unknown conversion specifier `" + std::string(1, conversion) + "`");
    }
    out += formatValue(v, spec);
    checkSize(out.size(), "string");
  }
  return Value::string(std::move(out), fmt.isMarkup());
}

}  // namespace smachac::tmpl
