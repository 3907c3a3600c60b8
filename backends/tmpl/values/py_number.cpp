// Python-compatible parsing of numeric strings (see py_number.h).
#include "backends/tmpl/values/py_number.h"

#include <charconv>
#include <cmath>
#include <string>

#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// digit ('_'? digit)*, appending the digits to `out`.
bool digitPart(std::string_view s, size_t& i, std::string& out) {
  if (i >= s.size() || !isDigit(s[i])) return false;
  out.push_back(s[i++]);
  while (i < s.size()) {
    if (isDigit(s[i])) {
      out.push_back(s[i++]);
    } else if (s[i] == '_' && i + 1 < s.size() && isDigit(s[i + 1])) {
      ++i;
    } else {
      break;
    }
  }
  return true;
}

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if ((a[i] | 0x20) != b[i]) return false;
  }
  return true;
}

int digitValue(char c) {
  if (isDigit(c)) return c - '0';
  c = static_cast<char>(c | 0x20);
  if (c >= 'a' && c <= 'z') return c - 'a' + 10;
  return 99;
}

}  // namespace

bool parsePythonFloat(std::string_view text, double& out) {
  std::string_view s = unicode::strip(text);
  bool negative = false;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    negative = s[0] == '-';
    s.remove_prefix(1);
  }
  if (equalsIgnoreCase(s, "inf") || equalsIgnoreCase(s, "infinity")) {
    out = negative ? -HUGE_VAL : HUGE_VAL;
    return true;
  }
  if (equalsIgnoreCase(s, "nan")) {
    out = negative ? -std::nan("") : std::nan("");
    return true;
  }
  std::string digits;
  size_t i = 0;
  bool integer = digitPart(s, i, digits);
  bool fraction = false;
  if (i < s.size() && s[i] == '.') {
    digits.push_back('.');
    ++i;
    fraction = digitPart(s, i, digits);
  }
  if (!integer && !fraction) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    digits.push_back('e');
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) digits.push_back(s[i++]);
    if (!digitPart(s, i, digits)) return false;
  }
  if (i != s.size()) return false;
  double value = 0;
  auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (result.ec == std::errc::result_out_of_range) {
    size_t e = digits.find('e');
    value = (e != std::string::npos && digits[e + 1] == '-') ? 0.0 : HUGE_VAL;
  }
  out = negative ? -value : value;
  return true;
}

bool parsePythonInt(std::string_view text, int base, int64_t& out, bool& overflow) {
  overflow = false;
  std::string_view s = unicode::strip(text);
  bool negative = false;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    negative = s[0] == '-';
    s.remove_prefix(1);
  }
  bool prefixed = false;
  if (s.size() >= 2 && s[0] == '0') {
    char p = static_cast<char>(s[1] | 0x20);
    int prefix_base = p == 'x' ? 16 : p == 'o' ? 8 : p == 'b' ? 2 : 0;
    if (prefix_base && (base == 0 || base == prefix_base)) {
      base = prefix_base;
      s.remove_prefix(2);
      prefixed = true;
    }
  }
  if (base == 0) {
    base = 10;
    if (s.size() > 1 && s[0] == '0' && s.find_first_not_of("0_") != std::string_view::npos)
      return false;
  }
  if (base < 2 || base > 36 || s.empty()) return false;
  uint64_t value = 0;
  bool last_digit = false;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '_') {
      if (!last_digit && !(prefixed && i == 0)) return false;
      last_digit = false;
      continue;
    }
    int d = digitValue(s[i]);
    if (d >= base) return false;
    if (value > (UINT64_MAX - static_cast<uint64_t>(d)) / static_cast<uint64_t>(base))
      overflow = true;
    value = value * static_cast<uint64_t>(base) + static_cast<uint64_t>(d);
    last_digit = true;
  }
  if (!last_digit) return false;
  if (overflow || value > static_cast<uint64_t>(INT64_MAX) + (negative ? 1 : 0)) {
    overflow = true;
    return false;
  }
  out = negative ? static_cast<int64_t>(0 - value) : static_cast<int64_t>(value);
  return true;
}

}  // namespace smachac::tmpl
