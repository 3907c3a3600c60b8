// Python 3's operators and built-ins on Values, for the callbacks smachac writes from portable
// expressions (`!expr 'counter + 1'`): the C++ target computes what the Python targets compute.
//   arithmetic   + - * on ints (64-bit; overflow throws ExpressionError, where Python would
//                grow the int) and doubles, an int and a double giving a double; + also joins
//                two strings or two lists; / always gives a double; // and % floor toward
//                minus infinity, % taking the sign of the divisor (Python's rules)
//   comparisons  == != on any values (1 == 1.0; true == 1); < <= > >= on two numbers or two
//                strings (by code point)
//   logic        `and`, `or` (the deciding operand, not a bool), `not`, `if ... else`
//   built-ins    len (strings in code points, lists, maps), min and max (of their arguments,
//                or of the items of their one argument), abs
// A bool is a number for arithmetic and comparisons, as in Python. Anything else throws
// ExpressionError with Python's message, e.g. "unsupported operand type(s) for +: 'int' and
// 'str'", or "division by zero".
#pragma once

#include <initializer_list>

#include "smachac/runtime/errors.h"
#include "smachac/runtime/value.h"

namespace smachac::runtime::ops {

/// An operation Python would refuse (TypeError, ZeroDivisionError, ValueError) or an int
/// overflow.
class ExpressionError : public Error {
 public:
  using Error::Error;
};

namespace detail {
// The operators on any operands; the inline ones below call them unless both are ints.
Value addAny(const Value& a, const Value& b);
Value subtractAny(const Value& a, const Value& b);
Value multiplyAny(const Value& a, const Value& b);
bool equalAny(const Value& a, const Value& b);
bool lessAny(const Value& a, const Value& b);
bool lessEqualAny(const Value& a, const Value& b);
bool greaterAny(const Value& a, const Value& b);
bool greaterEqualAny(const Value& a, const Value& b);
}  // namespace detail

// Two ints, what counters and limits hold, are added and compared inline.
inline Value add(const Value& a, const Value& b) {
  const int64_t *x = a.intIf(), *y = b.intIf();
  int64_t result = 0;
  if (x != nullptr && y != nullptr && !__builtin_add_overflow(*x, *y, &result)) return result;
  return detail::addAny(a, b);
}
inline Value subtract(const Value& a, const Value& b) {
  const int64_t *x = a.intIf(), *y = b.intIf();
  int64_t result = 0;
  if (x != nullptr && y != nullptr && !__builtin_sub_overflow(*x, *y, &result)) return result;
  return detail::subtractAny(a, b);
}
inline Value multiply(const Value& a, const Value& b) {
  const int64_t *x = a.intIf(), *y = b.intIf();
  int64_t result = 0;
  if (x != nullptr && y != nullptr && !__builtin_mul_overflow(*x, *y, &result)) return result;
  return detail::multiplyAny(a, b);
}
Value divide(const Value& a, const Value& b);
Value floorDivide(const Value& a, const Value& b);
Value modulo(const Value& a, const Value& b);
Value negate(const Value& a);
Value plus(const Value& a);

inline bool equal(const Value& a, const Value& b) {
  const int64_t *x = a.intIf(), *y = b.intIf();
  return x != nullptr && y != nullptr ? *x == *y : detail::equalAny(a, b);
}
inline bool notEqual(const Value& a, const Value& b) { return !equal(a, b); }
inline bool less(const Value& a, const Value& b) {
  const int64_t *x = a.intIf(), *y = b.intIf();
  return x != nullptr && y != nullptr ? *x < *y : detail::lessAny(a, b);
}
inline bool lessEqual(const Value& a, const Value& b) {
  const int64_t *x = a.intIf(), *y = b.intIf();
  return x != nullptr && y != nullptr ? *x <= *y : detail::lessEqualAny(a, b);
}
inline bool greater(const Value& a, const Value& b) {
  const int64_t *x = a.intIf(), *y = b.intIf();
  return x != nullptr && y != nullptr ? *x > *y : detail::greaterAny(a, b);
}
inline bool greaterEqual(const Value& a, const Value& b) {
  const int64_t *x = a.intIf(), *y = b.intIf();
  return x != nullptr && y != nullptr ? *x >= *y : detail::greaterEqualAny(a, b);
}

Value len(const Value& a);
Value abs(const Value& a);
/// min(a, b, ...) of several arguments, or of the items of a single one.
Value min(std::initializer_list<Value> arguments);
Value max(std::initializer_list<Value> arguments);

/// `a and b`, `a or b`: `b` is evaluated only when it decides.
template <class Right>
Value logicalAnd(const Value& a, Right&& b) {
  return a.truthy() ? Value(b()) : a;
}
template <class Right>
Value logicalOr(const Value& a, Right&& b) {
  return a.truthy() ? a : Value(b());
}

}  // namespace smachac::runtime::ops
