// Python 3's operators and built-ins on Values.
#include "smachac/runtime/expression_ops.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

namespace smachac::runtime::ops {
namespace {

/// Python's name of a value's type, as its error messages quote it.
std::string pyType(const Value& v) {
  switch (v.type()) {
    case ValueType::Null:
      return "'NoneType'";
    case ValueType::Bool:
      return "'bool'";
    case ValueType::Int:
      return "'int'";
    case ValueType::Double:
      return "'float'";
    case ValueType::String:
      return "'str'";
    case ValueType::List:
      return "'list'";
    case ValueType::Map:
      return "'dict'";
  }
  return "'object'";
}

[[noreturn]] void unsupported(const char* op, const Value& a, const Value& b) {
  throw ExpressionError("unsupported operand type(s) for " + std::string(op) + ": " + pyType(a) +
                        " and " + pyType(b));
}

[[noreturn]] void overflow(const char* op) {
  throw ExpressionError("integer overflow in `" + std::string(op) + "` (ints are 64-bit)");
}

/// A number as Python sees it: bools are the ints 0 and 1.
struct Number {
  bool is_int;
  int64_t i;
  double d;
  double real() const { return is_int ? static_cast<double>(i) : d; }
};

std::optional<Number> number(const Value& v) {
  switch (v.type()) {
    case ValueType::Bool:
      return Number{true, v.as<bool>() ? 1 : 0, 0};
    case ValueType::Int:
      return Number{true, v.as<int64_t>(), 0};
    case ValueType::Double:
      return Number{false, 0, v.as<double>()};
    default:
      return std::nullopt;
  }
}

template <class IntOp, class DoubleOp>
Value arithmetic(const char* op, const Value& a, const Value& b, IntOp int_op, DoubleOp double_op) {
  std::optional<Number> x = number(a), y = number(b);
  if (!x || !y) unsupported(op, a, b);
  if (x->is_int && y->is_int) {
    int64_t result = 0;
    if (int_op(x->i, y->i, &result)) overflow(op);
    return result;
  }
  return double_op(x->real(), y->real());
}

Value repeated(const Value& sequence, int64_t times) {
  if (sequence.type() == ValueType::String) {
    std::string out;
    for (int64_t k = 0; k < times; ++k) out += sequence.as<std::string>();
    return out;
  }
  List out;
  for (int64_t k = 0; k < times; ++k)
    out.insert(out.end(), sequence.list().begin(), sequence.list().end());
  return out;
}

bool isSequence(const Value& v) {
  return v.type() == ValueType::String || v.type() == ValueType::List;
}

/// Python's float divmod: the floored quotient and the remainder with the divisor's sign.
std::pair<double, double> floatDivmod(double x, double y) {
  double mod = std::fmod(x, y);
  double div = (x - mod) / y;
  if (mod != 0.0) {
    if ((y < 0) != (mod < 0)) {
      mod += y;
      div -= 1.0;
    }
  } else {
    mod = std::copysign(0.0, y);
  }
  double floor_div;
  if (div != 0.0) {
    floor_div = std::floor(div);
    if (div - floor_div > 0.5) floor_div += 1.0;
  } else {
    floor_div = std::copysign(0.0, x / y);
  }
  return {floor_div, mod};
}

enum class Order { Less, LessEqual, Greater, GreaterEqual };

const char* orderText(Order order) {
  switch (order) {
    case Order::Less:
      return "<";
    case Order::LessEqual:
      return "<=";
    case Order::Greater:
      return ">";
    case Order::GreaterEqual:
      return ">=";
  }
  return "<";
}

template <class T>
bool ordered(const T& a, const T& b, Order order) {
  switch (order) {
    case Order::Less:
      return a < b;
    case Order::LessEqual:
      return a <= b;
    case Order::Greater:
      return a > b;
    case Order::GreaterEqual:
      return a >= b;
  }
  return false;
}

bool compare(const Value& a, const Value& b, Order order) {
  std::optional<Number> x = number(a), y = number(b);
  if (x && y) {
    if (x->is_int && y->is_int) return ordered(x->i, y->i, order);
    // long double holds every int64 exactly on the platforms the runtime builds for.
    long double p = x->is_int ? static_cast<long double>(x->i) : x->d;
    long double q = y->is_int ? static_cast<long double>(y->i) : y->d;
    return ordered(p, q, order);
  }
  if (a.type() == ValueType::String && b.type() == ValueType::String) {
    // UTF-8 byte order is code point order.
    return ordered(a.as<std::string>(), b.as<std::string>(), order);
  }
  if (a.type() == ValueType::List && b.type() == ValueType::List) {
    const List& p = a.list();
    const List& q = b.list();
    for (size_t i = 0; i < p.size() && i < q.size(); ++i) {
      if (!equal(p[i], q[i])) return compare(p[i], q[i], order);
    }
    return ordered(p.size(), q.size(), order);
  }
  throw ExpressionError("'" + std::string(orderText(order)) +
                        "' not supported between instances of " + pyType(a) + " and " + pyType(b));
}

/// The items min() and max() choose from: the arguments, or the items of the only one.
List candidates(std::initializer_list<Value> arguments, const char* function) {
  if (arguments.size() != 1) return List(arguments.begin(), arguments.end());
  const Value& only = *arguments.begin();
  List items;
  switch (only.type()) {
    case ValueType::List:
      items = only.list();
      break;
    case ValueType::Map:
      for (const auto& [key, value] : only.map()) items.emplace_back(key);
      break;
    case ValueType::String: {
      const std::string& s = only.as<std::string>();
      for (size_t i = 0; i < s.size();) {
        size_t n = 1;
        while (i + n < s.size() && (static_cast<unsigned char>(s[i + n]) & 0xC0) == 0x80) ++n;
        items.emplace_back(s.substr(i, n));
        i += n;
      }
      break;
    }
    default:
      throw ExpressionError(pyType(only) + " object is not iterable");
  }
  if (items.empty()) throw ExpressionError(std::string(function) + "() arg is an empty sequence");
  return items;
}

}  // namespace

Value detail::addAny(const Value& a, const Value& b) {
  if (a.type() == ValueType::String && b.type() == ValueType::String) {
    return a.as<std::string>() + b.as<std::string>();
  }
  if (a.type() == ValueType::List && b.type() == ValueType::List) {
    List joined = a.list();
    joined.insert(joined.end(), b.list().begin(), b.list().end());
    return joined;
  }
  return arithmetic(
      "+", a, b, [](int64_t x, int64_t y, int64_t* r) { return __builtin_add_overflow(x, y, r); },
      [](double x, double y) { return x + y; });
}

Value detail::subtractAny(const Value& a, const Value& b) {
  return arithmetic(
      "-", a, b, [](int64_t x, int64_t y, int64_t* r) { return __builtin_sub_overflow(x, y, r); },
      [](double x, double y) { return x - y; });
}

Value detail::multiplyAny(const Value& a, const Value& b) {
  std::optional<Number> x = number(a), y = number(b);
  if (isSequence(a) && y && y->is_int) return repeated(a, y->i);
  if (isSequence(b) && x && x->is_int) return repeated(b, x->i);
  return arithmetic(
      "*", a, b, [](int64_t p, int64_t q, int64_t* r) { return __builtin_mul_overflow(p, q, r); },
      [](double p, double q) { return p * q; });
}

Value divide(const Value& a, const Value& b) {
  std::optional<Number> x = number(a), y = number(b);
  if (!x || !y) unsupported("/", a, b);
  if (y->real() == 0.0) throw ExpressionError("division by zero");
  return x->real() / y->real();
}

Value floorDivide(const Value& a, const Value& b) {
  std::optional<Number> x = number(a), y = number(b);
  if (!x || !y) unsupported("//", a, b);
  if (x->is_int && y->is_int) {
    if (y->i == 0) throw ExpressionError("integer division or modulo by zero");
    if (x->i == std::numeric_limits<int64_t>::min() && y->i == -1) overflow("//");
    int64_t q = x->i / y->i;
    if (x->i % y->i != 0 && ((x->i < 0) != (y->i < 0))) --q;
    return q;
  }
  if (y->real() == 0.0) throw ExpressionError("float floor division by zero");
  return floatDivmod(x->real(), y->real()).first;
}

Value modulo(const Value& a, const Value& b) {
  std::optional<Number> x = number(a), y = number(b);
  if (!x || !y) unsupported("%", a, b);
  if (x->is_int && y->is_int) {
    if (y->i == 0) throw ExpressionError("integer division or modulo by zero");
    if (y->i == -1) return int64_t{0};
    int64_t r = x->i % y->i;
    if (r != 0 && ((r < 0) != (y->i < 0))) r += y->i;
    return r;
  }
  if (y->real() == 0.0) throw ExpressionError("float modulo");
  return floatDivmod(x->real(), y->real()).second;
}

Value negate(const Value& a) {
  std::optional<Number> x = number(a);
  if (!x) throw ExpressionError("bad operand type for unary -: " + pyType(a));
  if (!x->is_int) return -x->d;
  if (x->i == std::numeric_limits<int64_t>::min()) overflow("-");
  return -x->i;
}

Value plus(const Value& a) {
  std::optional<Number> x = number(a);
  if (!x) throw ExpressionError("bad operand type for unary +: " + pyType(a));
  return x->is_int ? Value(x->i) : Value(x->d);
}

bool detail::equalAny(const Value& a, const Value& b) {
  std::optional<Number> x = number(a), y = number(b);
  if (x && y) {
    if (x->is_int && y->is_int) return x->i == y->i;
    long double p = x->is_int ? static_cast<long double>(x->i) : x->d;
    long double q = y->is_int ? static_cast<long double>(y->i) : y->d;
    return p == q;
  }
  if (a.type() != b.type()) return false;
  if (a.type() == ValueType::List) {
    const List& p = a.list();
    const List& q = b.list();
    if (p.size() != q.size()) return false;
    for (size_t i = 0; i < p.size(); ++i) {
      if (!equal(p[i], q[i])) return false;
    }
    return true;
  }
  if (a.type() == ValueType::Map) {
    const Map& p = a.map();
    const Map& q = b.map();
    if (p.size() != q.size()) return false;
    for (const auto& [key, value] : p) {
      auto it = q.find(key);
      if (it == q.end() || !equal(value, it->second)) return false;
    }
    return true;
  }
  return a == b;
}

bool detail::lessAny(const Value& a, const Value& b) { return compare(a, b, Order::Less); }
bool detail::lessEqualAny(const Value& a, const Value& b) {
  return compare(a, b, Order::LessEqual);
}
bool detail::greaterAny(const Value& a, const Value& b) { return compare(a, b, Order::Greater); }
bool detail::greaterEqualAny(const Value& a, const Value& b) {
  return compare(a, b, Order::GreaterEqual);
}

Value len(const Value& a) {
  switch (a.type()) {
    case ValueType::String: {
      int64_t n = 0;
      for (char c : a.as<std::string>()) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
      return n;
    }
    case ValueType::List:
      return static_cast<int64_t>(a.list().size());
    case ValueType::Map:
      return static_cast<int64_t>(a.map().size());
    default:
      throw ExpressionError("object of type " + pyType(a) + " has no len()");
  }
}

Value abs(const Value& a) {
  std::optional<Number> x = number(a);
  if (!x) throw ExpressionError("bad operand type for abs(): " + pyType(a));
  if (!x->is_int) return std::fabs(x->d);
  if (x->i == std::numeric_limits<int64_t>::min()) overflow("abs");
  return x->i < 0 ? -x->i : x->i;
}

Value min(std::initializer_list<Value> arguments) {
  List items = candidates(arguments, "min");
  Value best = items.front();
  for (size_t i = 1; i < items.size(); ++i) {
    if (less(items[i], best)) best = items[i];
  }
  return best;
}

Value max(std::initializer_list<Value> arguments) {
  List items = candidates(arguments, "max");
  Value best = items.front();
  for (size_t i = 1; i < items.size(); ++i) {
    if (greater(items[i], best)) best = items[i];
  }
  return best;
}

}  // namespace smachac::runtime::ops
