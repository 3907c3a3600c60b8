// Value::str() and Value::repr(): Python's spelling of values, so that what a C++ machine
// prints matches what the SMACH program generated from the same script prints.
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

#include "smachac/runtime/value.h"
#include "text.h"

namespace smachac::runtime {

namespace {

/// Python's repr(float): shortest round-trip digits, fixed notation for exponents in
/// [-4, 16), otherwise d.ddde+XX.
std::string pythonFloat(double d) {
  if (std::isnan(d)) return "nan";
  if (std::isinf(d)) return d > 0 ? "inf" : "-inf";
  char buffer[40];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, d, std::chars_format::scientific);
  std::string text(buffer, result.ptr);
  std::string sign = text[0] == '-' ? "-" : "";
  if (!sign.empty()) text.erase(0, 1);
  std::size_t e = text.find('e');
  int exponent = std::atoi(text.c_str() + e + 1);
  std::string digits;
  for (char c : text.substr(0, e)) {
    if (c != '.') digits += c;
  }
  if (exponent >= 16 || exponent < -4) {
    std::string mantissa = digits.substr(0, 1);
    if (digits.size() > 1) mantissa += "." + digits.substr(1);
    std::string exp = std::to_string(std::abs(exponent));
    if (exp.size() < 2) exp = "0" + exp;
    return sign + mantissa + (exponent < 0 ? "e-" : "e+") + exp;
  }
  if (exponent < 0) return sign + "0." + std::string(-exponent - 1, '0') + digits;
  auto integer_digits = static_cast<std::size_t>(exponent) + 1;
  if (digits.size() <= integer_digits) {
    return sign + digits + std::string(integer_digits - digits.size(), '0') + ".0";
  }
  return sign + digits.substr(0, integer_digits) + "." + digits.substr(integer_digits);
}

/// Python's repr(str): single quotes unless the text has one and no double quote.
std::string pythonString(const std::string& s) {
  char quote = (s.find('\'') != std::string::npos && s.find('"') == std::string::npos) ? '"' : '\'';
  std::string out;
  appendQuoted(out, s, quote, Escape::Python);
  return out;
}

std::string listRepr(const List& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += ", ";
    out += items[i].repr();
  }
  return out + "]";
}

std::string mapRepr(const Map& entries) {
  std::string out = "{";
  for (const auto& [key, value] : entries) {
    if (out.size() > 1) out += ", ";
    out += pythonString(key) + ": " + value.repr();
  }
  return out + "}";
}

}  // namespace

std::string Value::repr() const {
  switch (type()) {
    case ValueType::Null:
      return "None";
    case ValueType::Bool:
      return std::get<bool>(data_) ? "True" : "False";
    case ValueType::Int:
      return std::to_string(std::get<int64_t>(data_));
    case ValueType::Double:
      return pythonFloat(std::get<double>(data_));
    case ValueType::String:
      return pythonString(std::get<std::string>(data_));
    case ValueType::List:
      return listRepr(list());
    case ValueType::Map:
      return mapRepr(map());
  }
  return "?";
}

std::string Value::str() const {
  if (type() == ValueType::String) return std::get<std::string>(data_);
  return repr();
}

}  // namespace smachac::runtime
