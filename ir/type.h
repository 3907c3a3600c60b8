// Static types of userdata and template arguments, inferred from literals (and, later, from
// template meta declarations). Printed as: any, null, bool, int, float, string, expr,
// list<T>, map<string, T>. Element types join: int and float join to float; anything else
// that differs joins to any.
#pragma once

#include <memory>
#include <string>

#include "ir/value.h"

namespace smachac::ir {

class Type {
 public:
  enum class Kind : uint8_t { Any, Null, Bool, Int, Float, String, Expression, ListOf, MapOf };

  static Type any() { return Type(Kind::Any); }
  static Type of(Kind kind) { return Type(kind); }
  static Type listOf(Type element);
  static Type mapOf(Type element);
  /// The type of a literal.
  static Type ofValue(const Value& value);

  Kind kind() const { return kind_; }
  /// Element type of a list or map (Any otherwise).
  Type element() const;
  std::string str() const;

  /// The least type covering both (int ∨ float = float; otherwise any unless equal).
  static Type join(const Type& a, const Type& b);
  friend bool operator==(const Type& a, const Type& b);

 private:
  explicit Type(Kind kind) : kind_(kind) {}
  Kind kind_;
  std::shared_ptr<const Type> element_;
};

}  // namespace smachac::ir
