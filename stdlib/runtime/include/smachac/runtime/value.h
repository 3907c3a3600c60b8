// Value: one typed userdata value, as a script can write it.
//
//   null | bool | int (int64) | double | string | list (of Values) | map (string -> Value)
//
// Lists and maps are shared immutable trees (copying a Value never copies them), so a Value
// read from userdata is a cheap snapshot that other threads cannot change under the reader.
// `as<T>()` converts with checks and throws TypeError naming the type actually held.
#pragma once

#include <concepts>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace smachac::runtime {

// Declared before the List and Map aliases, whose names its enumerators reuse.
enum class ValueType : uint8_t { Null, Bool, Int, Double, String, List, Map };

class Value;
using List = std::vector<Value>;
using Map = std::map<std::string, Value, std::less<>>;

/// "null", "bool", "int", "double", "string", "list", "map".
std::string_view typeName(ValueType type);

class Value {
 public:
  Value() = default;
  Value(std::nullptr_t) {}
  Value(bool b) : data_(b) {}
  template <std::integral T>
  requires(!std::same_as<T, bool>) Value(T i) : data_(static_cast<int64_t>(i)) {}
  template <std::floating_point T>
  Value(T d) : data_(static_cast<double>(d)) {}
  Value(const char* s) : data_(std::string(s)) {}
  Value(std::string s) : data_(std::move(s)) {}
  Value(std::string_view s) : data_(std::string(s)) {}
  Value(List items);
  Value(Map entries);
  /// A list from any vector whose elements make Values: std::vector<double>, nested vectors...
  template <class T>
  requires std::constructible_from<Value, const T&> Value(const std::vector<T>& items)
      : Value(List(items.begin(), items.end())) {}

  ValueType type() const { return static_cast<ValueType>(data_.index()); }
  bool isNull() const { return type() == ValueType::Null; }
  /// Python truthiness: false, 0, 0.0, "", [], {} and null are false.
  bool truthy() const {
    if (const bool* b = std::get_if<bool>(&data_)) return *b;
    return truthyOther();
  }
  /// The int held, or null when the value is not an int: the fast paths of rt::ops.
  const int64_t* intIf() const { return std::get_if<int64_t>(&data_); }

  /// Checked conversion. Supported: bool, int, int64_t, double (also from an int), std::string,
  /// List, Map, Value, and std::vector of double, int64_t, std::string and std::vector<double>.
  template <class T>
  T as() const;

  /// The shared list or map; throw TypeError when the value is not one.
  const List& list() const;
  const Map& map() const;

  /// The type with its article, for messages: "a double", "an int", "null".
  std::string describe() const;
  /// Python's str(): what SMACH's print states show (strings bare, lists as [1, 'a', 2.5]).
  std::string str() const;
  /// Python's repr(): strings quoted.
  std::string repr() const;

  friend bool operator==(const Value& a, const Value& b);
  /// The same type and value (1 and 1.0 differ; lists and maps: the same shared one).
  bool identical(const Value& other) const;

 private:
  /// Throws TypeError: the value is not `expected` ("an int").
  [[noreturn]] void mismatch(const char* expected) const;
  /// truthy() of anything but a bool.
  bool truthyOther() const;

  std::variant<std::monostate, bool, int64_t, double, std::string, std::shared_ptr<const List>,
               std::shared_ptr<const Map>>
      data_;
};

template <class T>
T Value::as() const {
  static_assert(sizeof(T) == 0, "Value::as<T>: unsupported type");
}
// The scalar reads are inline: expressions and callbacks read a number at every step.
template <>
inline bool Value::as<bool>() const {
  if (const bool* b = std::get_if<bool>(&data_)) return *b;
  mismatch("a bool");
}
template <>
int Value::as<int>() const;
template <>
inline int64_t Value::as<int64_t>() const {
  if (const int64_t* i = std::get_if<int64_t>(&data_)) return *i;
  mismatch("an int");
}
template <>
inline double Value::as<double>() const {
  if (const double* d = std::get_if<double>(&data_)) return *d;
  if (const int64_t* i = std::get_if<int64_t>(&data_)) return static_cast<double>(*i);
  mismatch("a double");
}
template <>
std::string Value::as<std::string>() const;
template <>
List Value::as<List>() const;
template <>
Map Value::as<Map>() const;
template <>
Value Value::as<Value>() const;
template <>
std::vector<double> Value::as<std::vector<double>>() const;
template <>
std::vector<int64_t> Value::as<std::vector<int64_t>>() const;
template <>
std::vector<std::string> Value::as<std::vector<std::string>>() const;
template <>
std::vector<std::vector<double>> Value::as<std::vector<std::vector<double>>>() const;

}  // namespace smachac::runtime
