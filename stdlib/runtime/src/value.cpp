// Value: construction, truthiness, equality and the checked conversions of as<T>().
#include "smachac/runtime/value.h"

#include <limits>

#include "smachac/runtime/errors.h"

namespace smachac::runtime {

namespace {

using ListPtr = std::shared_ptr<const List>;
using MapPtr = std::shared_ptr<const Map>;

/// "a list with a string at index 1" when element `index` failed to convert.
[[noreturn]] void throwElementError(const char* expected, std::size_t index, const TypeError& e) {
  throw TypeError(expected, "a list with " + e.actual() + " at index " + std::to_string(index));
}

template <class T>
std::vector<T> listOf(const Value& value, const char* expected) {
  if (value.type() != ValueType::List) throw TypeError(expected, value.describe());
  const List& items = value.list();
  std::vector<T> out;
  out.reserve(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    try {
      out.push_back(items[i].as<T>());
    } catch (const TypeError& e) {
      throwElementError(expected, i, e);
    }
  }
  return out;
}

}  // namespace

std::string_view typeName(ValueType type) {
  switch (type) {
    case ValueType::Null:
      return "null";
    case ValueType::Bool:
      return "bool";
    case ValueType::Int:
      return "int";
    case ValueType::Double:
      return "double";
    case ValueType::String:
      return "string";
    case ValueType::List:
      return "list";
    case ValueType::Map:
      return "map";
  }
  return "?";
}

Value::Value(List items) : data_(std::make_shared<const List>(std::move(items))) {}
Value::Value(Map entries) : data_(std::make_shared<const Map>(std::move(entries))) {}

bool Value::identical(const Value& other) const { return data_ == other.data_; }

bool Value::truthyOther() const {
  switch (type()) {
    case ValueType::Null:
      return false;
    case ValueType::Bool:
      return std::get<bool>(data_);
    case ValueType::Int:
      return std::get<int64_t>(data_) != 0;
    case ValueType::Double:
      return std::get<double>(data_) != 0.0;
    case ValueType::String:
      return !std::get<std::string>(data_).empty();
    case ValueType::List:
      return !list().empty();
    case ValueType::Map:
      return !map().empty();
  }
  return false;
}

const List& Value::list() const {
  if (type() != ValueType::List) throw TypeError("a list", describe());
  return *std::get<ListPtr>(data_);
}

const Map& Value::map() const {
  if (type() != ValueType::Map) throw TypeError("a map", describe());
  return *std::get<MapPtr>(data_);
}

std::string Value::describe() const {
  switch (type()) {
    case ValueType::Null:
      return "null";
    case ValueType::Int:
      return "an int";
    default:
      return "a " + std::string(typeName(type()));
  }
}

bool operator==(const Value& a, const Value& b) {
  if (a.type() != b.type()) return false;
  switch (a.type()) {
    case ValueType::List:
      return a.list() == b.list();
    case ValueType::Map:
      return a.map() == b.map();
    default:
      return a.data_ == b.data_;
  }
}

void Value::mismatch(const char* expected) const { throw TypeError(expected, describe()); }

template <>
int Value::as<int>() const {
  int64_t i = as<int64_t>();
  if (i < std::numeric_limits<int>::min() || i > std::numeric_limits<int>::max()) {
    throw TypeError("a 32-bit int", "an int out of range (" + std::to_string(i) + ")");
  }
  return static_cast<int>(i);
}

template <>
std::string Value::as<std::string>() const {
  if (type() != ValueType::String) throw TypeError("a string", describe());
  return std::get<std::string>(data_);
}

template <>
List Value::as<List>() const {
  return list();
}

template <>
Map Value::as<Map>() const {
  return map();
}

template <>
Value Value::as<Value>() const {
  return *this;
}

template <>
std::vector<double> Value::as<std::vector<double>>() const {
  return listOf<double>(*this, "a list of doubles");
}

template <>
std::vector<int64_t> Value::as<std::vector<int64_t>>() const {
  return listOf<int64_t>(*this, "a list of ints");
}

template <>
std::vector<std::string> Value::as<std::vector<std::string>>() const {
  return listOf<std::string>(*this, "a list of strings");
}

template <>
std::vector<std::vector<double>> Value::as<std::vector<std::vector<double>>>() const {
  return listOf<std::vector<double>>(*this, "a list of lists of doubles");
}

}  // namespace smachac::runtime
