// rt::ops: Python 3's operators and built-ins on Values (the values and messages below are
// CPython's).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "smachac/runtime/expression_ops.h"

namespace rt = smachac::runtime;
namespace ops = smachac::runtime::ops;

TEST_CASE("floor division and modulo round toward minus infinity") {
  CHECK(ops::floorDivide(-7, 2) == rt::Value(-4));
  CHECK(ops::floorDivide(7, -2) == rt::Value(-4));
  CHECK(ops::modulo(-7, 3) == rt::Value(2));
  CHECK(ops::modulo(7, -3) == rt::Value(-2));
  CHECK(ops::floorDivide(-7.5, 2) == rt::Value(-4.0));
  CHECK(ops::modulo(-7.5, 2) == rt::Value(0.5));
  CHECK(ops::modulo(7.5, -2) == rt::Value(-0.5));
  CHECK(std::signbit(ops::modulo(-4.0, 2).as<double>()) == false);
  CHECK(ops::modulo(std::numeric_limits<int64_t>::min(), -1) == rt::Value(0));
}

TEST_CASE("arithmetic mixes ints and doubles as Python does") {
  CHECK(ops::add(1, 2) == rt::Value(3));
  CHECK(ops::add(1, 2.5) == rt::Value(3.5));
  CHECK(ops::divide(4, 2) == rt::Value(2.0));
  CHECK(ops::divide(5, 2) == rt::Value(2.5));
  CHECK(ops::multiply(true, 3) == rt::Value(3));
  CHECK(ops::plus(true) == rt::Value(1));
  CHECK(ops::negate(2.5) == rt::Value(-2.5));
  CHECK(ops::add("ab", "c") == rt::Value("abc"));
  CHECK(ops::add(rt::List{1}, rt::List{2}) == rt::Value(rt::List{1, 2}));
  CHECK(ops::multiply("ab", 2) == rt::Value("abab"));
  CHECK(ops::multiply(0, rt::List{1}) == rt::Value(rt::List{}));
}

TEST_CASE("refused operations throw Python's messages") {
  CHECK_THROWS_WITH_AS(ops::add(1, "a"), "unsupported operand type(s) for +: 'int' and 'str'",
                       ops::ExpressionError);
  CHECK_THROWS_WITH(ops::divide(1, 0), "division by zero");
  CHECK_THROWS_WITH(ops::floorDivide(1, 0), "integer division or modulo by zero");
  CHECK_THROWS_WITH(ops::modulo(1.0, 0), "float modulo");
  CHECK_THROWS_WITH(ops::negate("a"), "bad operand type for unary -: 'str'");
  CHECK_THROWS_WITH(ops::less(1, "a"), "'<' not supported between instances of 'int' and 'str'");
  CHECK_THROWS_WITH(ops::len(3), "object of type 'int' has no len()");
  CHECK_THROWS_WITH(ops::min({rt::Value(rt::List{})}), "min() arg is an empty sequence");
  CHECK_THROWS_WITH(ops::max({rt::Value(5)}), "'int' object is not iterable");
  CHECK_THROWS_WITH(ops::add(std::numeric_limits<int64_t>::max(), 1),
                    "integer overflow in `+` (ints are 64-bit)");
  CHECK_THROWS_AS(ops::abs(std::numeric_limits<int64_t>::min()), ops::ExpressionError);
}

TEST_CASE("two ints are computed inline; overflow and other operands as in general") {
  constexpr int64_t kMax = std::numeric_limits<int64_t>::max();
  constexpr int64_t kMin = std::numeric_limits<int64_t>::min();
  CHECK(ops::add(-3, 5) == rt::Value(2));
  CHECK(ops::subtract(3, 5) == rt::Value(-2));
  CHECK(ops::multiply(-4, 5) == rt::Value(-20));
  CHECK(ops::add(2, 0.5).type() == rt::ValueType::Double);
  CHECK(ops::add(true, 1) == rt::Value(2));
  CHECK_THROWS_WITH(ops::subtract(kMin, 1), "integer overflow in `-` (ints are 64-bit)");
  CHECK_THROWS_WITH(ops::multiply(kMax, 2), "integer overflow in `*` (ints are 64-bit)");
  CHECK(ops::less(kMin, kMax));
  CHECK(ops::lessEqual(-1, -1));
  CHECK_FALSE(ops::greater(-1, 0));
  CHECK(ops::greaterEqual(0, -1));
  CHECK(ops::notEqual(1, 2));
  CHECK_FALSE(ops::equal(kMax, kMax - 1));
}

TEST_CASE("comparisons") {
  CHECK(ops::equal(1, 1.0));
  CHECK(ops::equal(true, 1));
  CHECK_FALSE(ops::equal(1, "1"));
  CHECK(ops::equal(rt::List{1, 2}, rt::List{1.0, 2}));
  CHECK(ops::less("abc", "abd"));
  CHECK(ops::less("z", "\xc3\xa9"));  // code point order: 'z' < 'é'
  CHECK(ops::less(rt::List{1, 2}, rt::List{1, 3}));
  CHECK(ops::less(rt::List{1}, rt::List{1, 0}));
  CHECK_FALSE(ops::lessEqual(std::nan(""), 1));
  CHECK_FALSE(ops::greaterEqual(std::nan(""), 1));
  CHECK(ops::greater(9007199254740993, 9007199254740992.0));
}

TEST_CASE("built-ins and logic") {
  CHECK(ops::len("h\xc3\xa9llo") == rt::Value(5));
  CHECK(ops::len(rt::Map{{"a", 1}}) == rt::Value(1));
  CHECK(ops::min({rt::Value(rt::List{3, 1, 2})}) == rt::Value(1));
  CHECK(ops::max({rt::Value(3), rt::Value(4.5), rt::Value(2)}) == rt::Value(4.5));
  CHECK(ops::min({rt::Value(1), rt::Value(1.0)}).type() == rt::ValueType::Int);
  CHECK(ops::max({rt::Value("b\xc3\xa9")}) == rt::Value("\xc3\xa9"));
  CHECK(ops::abs(-2.5) == rt::Value(2.5));
  CHECK(ops::logicalOr("", [] { return rt::Value("fallback"); }) == rt::Value("fallback"));
  CHECK(ops::logicalAnd(0, [] { return rt::Value(5); }) == rt::Value(0));
  bool evaluated = false;
  ops::logicalOr(1, [&] {
    evaluated = true;
    return rt::Value(2);
  });
  CHECK_FALSE(evaluated);
}
