// Typed literals: the values of userdata, params and template arguments, and the YAML
// document tree the frontend works on. Every value and every mapping key keeps its location.
//
//   null | bool | int (int64) | float (double) | string | expression (`code` in backticks)
//   | list | map (insertion-ordered)
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "ir/support/source_loc.h"

namespace smachac::ir {

enum class ValueKind : uint8_t { Null, Bool, Int, Float, String, Expression, List, Map };

std::string_view valueKindName(ValueKind kind);

struct Value;
struct MapEntry;

using List = std::vector<Value>;
using Map = std::vector<MapEntry>;

struct PortableExpr;

/// Target code written in backticks in the script (`lambda ud: ud.x`), without the backticks;
/// or a portable expression (`!expr 'x + 1'`, ir/expr.h): then `code` is its text as written
/// and `portable` its tree, until a backend replaces it with target code.
struct Expression {
  std::string code;
  std::shared_ptr<const PortableExpr> portable;
  friend bool operator==(const Expression& a, const Expression& b) {
    return a.code == b.code && (a.portable == nullptr) == (b.portable == nullptr);
  }
};

/// Expressions are rare in a document tree and immutable once made: the variant holds them
/// behind a shared pointer, so that every value stays 16 bytes smaller (a big script's tree is
/// mostly strings, lists and maps).
using ExpressionPtr = std::shared_ptr<const Expression>;

struct Value {
  std::variant<std::monostate, bool, int64_t, double, std::string, ExpressionPtr, List, Map> data;
  SourceLoc loc;
  /// A string the script forced to stay a string (YAML `!str` tag): never rendered bare.
  bool forced_string = false;
  /// Non-zero when this value is the value of a behavior parameter (`Module::addBehaviorParam`):
  /// a `[params, x]` lookup of the script's or a sub-script's `params` copies it with the
  /// value. Targets with behavior parameters (FlexBE) refer to the parameter instead.
  uint32_t behavior_param = 0;

  static Value null(SourceLoc loc = {});
  static Value boolean(bool b, SourceLoc loc = {});
  static Value integer(int64_t i, SourceLoc loc = {});
  static Value real(double d, SourceLoc loc = {});
  static Value string(std::string s, SourceLoc loc = {});
  static Value expression(std::string code, SourceLoc loc = {});
  static Value portable(std::shared_ptr<const PortableExpr> expr, SourceLoc loc = {});
  static Value list(List items, SourceLoc loc = {});
  static Value map(Map entries, SourceLoc loc = {});

  ValueKind kind() const { return static_cast<ValueKind>(data.index()); }
  bool isNull() const { return kind() == ValueKind::Null; }
  bool isString() const { return kind() == ValueKind::String; }
  bool isList() const { return kind() == ValueKind::List; }
  bool isMap() const { return kind() == ValueKind::Map; }

  bool asBool() const { return std::get<bool>(data); }
  int64_t asInt() const { return std::get<int64_t>(data); }
  double asFloat() const { return std::get<double>(data); }
  const std::string& asString() const { return std::get<std::string>(data); }
  const Expression& asExpression() const { return *std::get<ExpressionPtr>(data); }
  /// The tree of a portable expression (`!expr`), or nullptr for any other value.
  const PortableExpr* asPortable() const;
  const List& asList() const { return std::get<List>(data); }
  List& asList() { return std::get<List>(data); }
  const Map& asMap() const { return std::get<Map>(data); }
  Map& asMap() { return std::get<Map>(data); }

  /// The entry of a map value with this key, or nullptr (also for non-maps).
  const Value* find(std::string_view key) const;
  Value* find(std::string_view key);
};

struct MapEntry {
  std::string key;
  SourceLoc key_loc;
  Value value;
};

/// Structural equality of values (locations ignored).
bool sameValue(const Value& a, const Value& b);

/// A short description for diagnostics: "a mapping", "a list", "the string `x`", "null", ...
std::string describeValue(const Value& value);

}  // namespace smachac::ir
