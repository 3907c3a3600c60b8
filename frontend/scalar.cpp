// YAML 1.2 core schema scalar resolution.
#include "frontend/scalar.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace smachac::frontend {
namespace {

bool isDigits(std::string_view s, int base) {
  if (s.empty()) return false;
  for (char c : s) {
    bool ok = base == 16  ? std::isxdigit(static_cast<unsigned char>(c)) != 0
              : base == 8 ? (c >= '0' && c <= '7')
                          : (c >= '0' && c <= '9');
    if (!ok) return false;
  }
  return true;
}

/// Parses [-+]?digits, 0o..., 0x...; nullopt when `text` is not an integer.
std::optional<ScalarResult> parseInt(std::string_view text, SourceLoc loc) {
  std::string_view body = text;
  bool negative = false;
  int base = 10;
  if (body.starts_with("0o") && isDigits(body.substr(2), 8)) {
    base = 8;
    body.remove_prefix(2);
  } else if (body.starts_with("0x") && isDigits(body.substr(2), 16)) {
    base = 16;
    body.remove_prefix(2);
  } else {
    if (!body.empty() && (body[0] == '-' || body[0] == '+')) {
      negative = body[0] == '-';
      body.remove_prefix(1);
    }
    if (!isDigits(body, 10)) return std::nullopt;
  }
  uint64_t magnitude = 0;
  auto [end, error] = std::from_chars(body.data(), body.data() + body.size(), magnitude, base);
  uint64_t limit = negative ? uint64_t(std::numeric_limits<int64_t>::max()) + 1
                            : uint64_t(std::numeric_limits<int64_t>::max());
  if (error != std::errc() || magnitude > limit) {
    return ScalarResult{ir::Value::integer(0, loc), true};
  }
  int64_t v = negative ? static_cast<int64_t>(0 - magnitude) : static_cast<int64_t>(magnitude);
  return ScalarResult{ir::Value::integer(v, loc), false};
}

bool isFloatSyntax(std::string_view s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  size_t int_digits = 0, frac_digits = 0;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++int_digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++frac_digits;
  }
  if (int_digits + frac_digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    size_t exp_digits = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  return i == s.size();
}

std::optional<double> parseFloat(std::string_view s) {
  if (s == ".inf" || s == ".Inf" || s == ".INF" || s == "+.inf" || s == "+.Inf" || s == "+.INF") {
    return std::numeric_limits<double>::infinity();
  }
  if (s == "-.inf" || s == "-.Inf" || s == "-.INF") return -std::numeric_limits<double>::infinity();
  if (s == ".nan" || s == ".NaN" || s == ".NAN") return std::numeric_limits<double>::quiet_NaN();
  if (!isFloatSyntax(s)) return std::nullopt;
  std::string_view body = s.starts_with('+') ? s.substr(1) : s;
  double v = 0;
  auto [end, error] = std::from_chars(body.data(), body.data() + body.size(), v);
  if (error == std::errc::result_out_of_range)
    return std::strtod(std::string(body).c_str(), nullptr);
  if (error != std::errc()) return std::nullopt;
  return v;
}

/// A plain scalar whose first byte starts no null, bool, int or float of the core schema: a
/// letter but n, t, f in either case (most scalars of a script: names and keys).
bool isSurelyString(std::string_view text) {
  char c = text.empty() ? '\0' : text[0];
  bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  return letter && std::string_view("nNtTfF").find(c) == std::string_view::npos;
}

}  // namespace

ir::Value textValue(std::string_view text, SourceLoc loc) {
  if (text.size() >= 2 && text.front() == '`' && text.back() == '`') {
    return ir::Value::expression(std::string(text.substr(1, text.size() - 2)), loc);
  }
  return ir::Value::string(std::string(text), loc);
}

ScalarResult resolveScalar(std::string_view text, ScalarStyle style, std::string_view tag,
                           SourceLoc loc) {
  if (tag == "!str" || tag == "tag:yaml.org,2002:str") {
    ir::Value v = ir::Value::string(std::string(text), loc);
    v.forced_string = true;
    return {std::move(v)};
  }
  if (style == ScalarStyle::Quoted || isSurelyString(text)) return {textValue(text, loc)};
  if (text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL") {
    return {ir::Value::null(loc)};
  }
  if (text == "true" || text == "True" || text == "TRUE") return {ir::Value::boolean(true, loc)};
  if (text == "false" || text == "False" || text == "FALSE") {
    return {ir::Value::boolean(false, loc)};
  }
  if (std::optional<ScalarResult> i = parseInt(text, loc)) return std::move(*i);
  if (std::optional<double> f = parseFloat(text)) return {ir::Value::real(*f, loc)};
  return {textValue(text, loc)};
}

}  // namespace smachac::frontend
