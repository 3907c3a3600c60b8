// Python float repr on top of std::to_chars' shortest round-trip digits.
#include "ir/support/python_float.h"

#include <charconv>
#include <cmath>
#include <string_view>

namespace smachac {
namespace {

/// Shortest round-trip digits and decimal exponent: value = 0.d1d2d3... * 10^exponent.
void shortestDigits(double value, std::string& digits, int& exponent) {
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
  std::string_view text(buffer, result.ptr - buffer);  // d.ddde[+-]XX
  size_t e = text.find('e');
  std::string_view mantissa = text.substr(0, e);
  exponent = std::stoi(std::string(text.substr(e + 1))) + 1;
  digits.clear();
  for (char c : mantissa) {
    if (c != '.') digits += c;
  }
  while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
}

std::string exponentForm(const std::string& digits, int exponent) {
  std::string out(1, digits[0]);
  if (digits.size() > 1) {
    out += '.';
    out.append(digits, 1);
  }
  int e = exponent - 1;
  out += e < 0 ? "e-" : "e+";
  int magnitude = std::abs(e);
  if (magnitude < 10) out += '0';
  out += std::to_string(magnitude);
  return out;
}

std::string positionalForm(const std::string& digits, int exponent) {
  std::string out;
  if (exponent <= 0) {
    out = "0.";
    out.append(static_cast<size_t>(-exponent), '0');
    out += digits;
  } else if (static_cast<size_t>(exponent) >= digits.size()) {
    out = digits;
    out.append(exponent - digits.size(), '0');
    out += ".0";
  } else {
    out.assign(digits, 0, exponent);
    out += '.';
    out.append(digits, exponent);
  }
  return out;
}

}  // namespace

std::string pythonFloatRepr(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  std::string out = std::signbit(value) ? "-" : "";
  if (value == 0) return out += "0.0";
  std::string digits;
  int exponent = 0;
  shortestDigits(std::fabs(value), digits, exponent);
  bool use_exponent = exponent - 1 < -4 || exponent - 1 >= 16;
  out += use_exponent ? exponentForm(digits, exponent) : positionalForm(digits, exponent);
  return out;
}

}  // namespace smachac
