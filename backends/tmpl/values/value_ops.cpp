// Python semantics of values: comparisons, hashing, arithmetic, membership and iteration.
#include "backends/tmpl/values/value_ops.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "backends/tmpl/error.h"
#include "backends/tmpl/limits.h"
#include "backends/tmpl/values/py_format.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

constexpr double kTwo63 = 9223372036854775808.0;

[[noreturn]] void failUndefined(const Value& v) { fail(v.undefinedMessage()); }

void checkDefined(const Value& a, const Value& b) {
  if (a.isUndefined()) failUndefined(a);
  if (b.isUndefined()) failUndefined(b);
}

// -1, 0, 1, or 2 when unordered (NaN).
int compareIntFloat(int64_t i, double d) {
  if (std::isnan(d)) return 2;
  if (d >= kTwo63) return -1;
  if (d < -kTwo63) return 1;
  double t = std::trunc(d);
  auto ti = static_cast<int64_t>(t);
  if (i != ti) return i < ti ? -1 : 1;
  if (d == t) return 0;
  return d > t ? -1 : 1;
}

// -1, 0, 1, or 2 when unordered.
int compareNumbers(const Value& a, const Value& b) {
  if (!a.isFloat() && !b.isFloat()) {
    int64_t x = a.integral();
    int64_t y = b.integral();
    return x < y ? -1 : x > y ? 1 : 0;
  }
  if (a.isFloat() && b.isFloat()) {
    double x = a.f();
    double y = b.f();
    if (std::isnan(x) || std::isnan(y)) return 2;
    return x < y ? -1 : x > y ? 1 : 0;
  }
  if (a.isFloat()) {
    int c = compareIntFloat(b.integral(), a.f());
    return c == 2 ? 2 : -c;
  }
  return compareIntFloat(a.integral(), b.f());
}

bool sequenceEquals(const std::vector<Value>& x, const std::vector<Value>& y) {
  if (x.size() != y.size()) return false;
  DepthGuard guard;
  for (size_t i = 0; i < x.size(); ++i) {
    if (x[i].identity() && x[i].identity() == y[i].identity()) continue;
    if (!equals(x[i], y[i])) return false;
  }
  return true;
}

bool dictEquals(const DictObject& x, const DictObject& y) {
  if (x.size() != y.size()) return false;
  DepthGuard guard;
  for (const auto& [key, value] : x.entries()) {
    const Value* other = y.find(key);
    if (!other || !equals(value, *other)) return false;
  }
  return true;
}

bool sequenceLess(const std::vector<Value>& x, const std::vector<Value>& y) {
  DepthGuard guard;
  size_t n = std::min(x.size(), y.size());
  for (size_t i = 0; i < n; ++i) {
    if (x[i].identity() && x[i].identity() == y[i].identity()) continue;
    if (!equals(x[i], y[i])) return lessThan(x[i], y[i]);
  }
  return x.size() < y.size();
}

size_t mixHash(uint64_t x) {
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdull;
  x ^= x >> 33;
  return static_cast<size_t>(x | 1);
}

[[noreturn]] void failOperands(BinOp op, const Value& a, const Value& b) {
  fail("unsupported operand types for `" + std::string(binOpSymbol(op)) + "`: `" +
       std::string(typeName(a)) + "` and `" + std::string(typeName(b)) + "`");
}

int64_t addInts(int64_t a, int64_t b) {
  int64_t r = 0;
  if (__builtin_add_overflow(a, b, &r)) fail("integer overflow");
  return r;
}

int64_t subInts(int64_t a, int64_t b) {
  int64_t r = 0;
  if (__builtin_sub_overflow(a, b, &r)) fail("integer overflow");
  return r;
}

int64_t mulInts(int64_t a, int64_t b) {
  int64_t r = 0;
  if (__builtin_mul_overflow(a, b, &r)) fail("integer overflow");
  return r;
}

Value addStrings(const Value& a, const Value& b) {
  bool markup = a.isMarkup() || b.isMarkup();
  std::string out;
  checkSize(a.s().size() + b.s().size(), "string");
  out.reserve(a.s().size() + b.s().size());
  if (markup && !a.isMarkup()) {
    out += htmlEscape(a.s());
  } else {
    out += a.s();
  }
  if (markup && !b.isMarkup()) {
    out += htmlEscape(b.s());
  } else {
    out += b.s();
  }
  return Value::string(std::move(out), markup);
}

Value add(const Value& a, const Value& b) {
  if (a.isNumber() && b.isNumber()) {
    if (a.isFloat() || b.isFloat()) return Value::real(a.number() + b.number());
    return Value::integer(addInts(a.integral(), b.integral()));
  }
  if (a.isString() && b.isString()) return addStrings(a, b);
  if ((a.isList() && b.isList()) || (a.isTuple() && b.isTuple())) {
    std::vector<Value> items = a.list().items();
    checkSize(items.size() + b.list().items().size(), "list");
    items.insert(items.end(), b.list().items().begin(), b.list().items().end());
    return a.isList() ? Value::newList(std::move(items)) : Value::newTuple(std::move(items));
  }
  failOperands(BinOp::Add, a, b);
}

Value repeat(const Value& seq, int64_t times) {
  if (times < 0) times = 0;
  if (seq.isString()) {
    checkSize(seq.s().size() * static_cast<size_t>(times), "string");
    const std::string& text = seq.s();
    if (text.size() == 1) {  // `' ' * indent`, the common case: one fill
      return Value::string(std::string(static_cast<size_t>(times), text[0]), seq.isMarkup());
    }
    std::string out;
    out.reserve(text.size() * static_cast<size_t>(times));
    for (int64_t i = 0; i < times; ++i) out += text;
    return Value::string(std::move(out), seq.isMarkup());
  }
  const auto& items = seq.list().items();
  checkSize(items.size() * static_cast<size_t>(times), "list");
  std::vector<Value> out;
  out.reserve(items.size() * static_cast<size_t>(times));
  for (int64_t i = 0; i < times; ++i) out.insert(out.end(), items.begin(), items.end());
  return seq.isList() ? Value::newList(std::move(out)) : Value::newTuple(std::move(out));
}

bool isIntLike(const Value& v) { return v.isInt() || v.isBool(); }

Value multiply(const Value& a, const Value& b) {
  if (a.isNumber() && b.isNumber()) {
    if (a.isFloat() || b.isFloat()) return Value::real(a.number() * b.number());
    return Value::integer(mulInts(a.integral(), b.integral()));
  }
  bool a_seq = a.isString() || a.isListOrTuple();
  bool b_seq = b.isString() || b.isListOrTuple();
  if (a_seq && isIntLike(b)) return repeat(a, b.integral());
  if (b_seq && isIntLike(a)) return repeat(b, a.integral());
  failOperands(BinOp::Mul, a, b);
}

double pyFloatMod(double x, double y) {
  double mod = std::fmod(x, y);
  if (mod != 0.0) {
    if ((y < 0) != (mod < 0)) mod += y;
  } else {
    mod = std::copysign(0.0, y);
  }
  return mod;
}

double pyFloatFloorDiv(double x, double y) {
  double mod = std::fmod(x, y);
  double div = (x - mod) / y;
  if (mod != 0.0 && ((y < 0) != (mod < 0))) div -= 1.0;
  if (div == 0.0) return std::copysign(0.0, x / y);
  double floor_div = std::floor(div);
  if (div - floor_div > 0.5) floor_div += 1.0;
  return floor_div;
}

Value divideLike(BinOp op, const Value& a, const Value& b) {
  if (!a.isNumber() || !b.isNumber()) {
    if (op == BinOp::Mod && a.isString()) return percentFormat(a, b);
    failOperands(op, a, b);
  }
  if (b.number() == 0.0) {
    fail(op == BinOp::Mod ? "modulo by zero" : "division by zero");
  }
  if (op == BinOp::Div) return Value::real(a.number() / b.number());
  if (a.isFloat() || b.isFloat()) {
    double x = a.number();
    double y = b.number();
    return Value::real(op == BinOp::Mod ? pyFloatMod(x, y) : pyFloatFloorDiv(x, y));
  }
  int64_t x = a.integral();
  int64_t y = b.integral();
  if (x == std::numeric_limits<int64_t>::min() && y == -1) {
    if (op == BinOp::Mod) return Value::integer(0);
    fail("integer overflow");
  }
  int64_t q = x / y;
  int64_t r = x % y;
  if (r != 0 && ((r < 0) != (y < 0))) {
    q -= 1;
    r += y;
  }
  return Value::integer(op == BinOp::Mod ? r : q);
}

Value power(const Value& a, const Value& b) {
  if (!a.isNumber() || !b.isNumber()) failOperands(BinOp::Pow, a, b);
  if (!a.isFloat() && !b.isFloat() && b.integral() >= 0) {
    int64_t base = a.integral();
    int64_t exp = b.integral();
    int64_t result = 1;
    while (exp > 0) {
      if (exp & 1) result = mulInts(result, base);
      exp >>= 1;
      if (exp > 0) base = mulInts(base, base);
    }
    return Value::integer(result);
  }
  double x = a.number();
  double y = b.number();
  if (x == 0.0 && y < 0) fail("0.0 cannot be raised to a negative power");
  if (x < 0 && std::isfinite(y) && y != std::floor(y)) fail("complex results are not supported");
  double r = std::pow(x, y);
  if (std::isinf(r) && std::isfinite(x) && std::isfinite(y)) fail("numerical result out of range");
  return Value::real(r);
}

}  // namespace

std::string_view kindName(Kind kind) {
  switch (kind) {
    case Kind::Undefined:
      return "Undefined";
    case Kind::None:
      return "NoneType";
    case Kind::Bool:
      return "bool";
    case Kind::Int:
      return "int";
    case Kind::Float:
      return "float";
    case Kind::String:
      return "str";
    case Kind::List:
      return "list";
    case Kind::Tuple:
      return "tuple";
    case Kind::Dict:
      return "dict";
    case Kind::Object:
      return "object";
  }
  return "object";
}

std::string_view typeName(const Value& v) {
  if (v.isObject()) return v.object()->typeName();
  return kindName(v.kind());
}

bool truthy(const Value& v) {
  switch (v.kind()) {
    case Kind::Undefined:
    case Kind::None:
      return false;
    case Kind::Bool:
      return v.b();
    case Kind::Int:
      return v.i() != 0;
    case Kind::Float:
      return v.f() != 0.0;
    case Kind::String:
      return !v.s().empty();
    case Kind::List:
    case Kind::Tuple:
      return !v.list().items().empty();
    case Kind::Dict:
      return !v.dict().empty();
    case Kind::Object:
      return true;
  }
  return true;
}

bool equals(const Value& a, const Value& b) {
  if (a.isNumber() && b.isNumber()) return compareNumbers(a, b) == 0;
  if (a.kind() != b.kind()) return false;
  switch (a.kind()) {
    case Kind::Undefined:
    case Kind::None:
      return true;
    case Kind::String:
      return a.identity() == b.identity() || sameText(a.s(), b.s());
    case Kind::List:
    case Kind::Tuple:
      return a.identity() == b.identity() || sequenceEquals(a.list().items(), b.list().items());
    case Kind::Dict:
      return a.identity() == b.identity() || dictEquals(a.dict(), b.dict());
    default:
      return a.identity() == b.identity();
  }
}

bool lessThan(const Value& a, const Value& b) {
  checkDefined(a, b);
  if (a.isNumber() && b.isNumber()) return compareNumbers(a, b) == -1;
  if (a.isString() && b.isString()) return a.s() < b.s();
  if ((a.isList() && b.isList()) || (a.isTuple() && b.isTuple())) {
    return sequenceLess(a.list().items(), b.list().items());
  }
  fail("`<` is not supported between instances of `" + std::string(typeName(a)) + "` and `" +
       std::string(typeName(b)) + "`");
}

size_t hashOf(const Value& v) {
  switch (v.kind()) {
    case Kind::Undefined:
      return 7;
    case Kind::None:
      return 3;
    case Kind::Bool:
    case Kind::Int:
      return mixHash(static_cast<uint64_t>(v.integral()));
    case Kind::Float: {
      double d = v.f();
      if (d == std::trunc(d) && d >= -kTwo63 && d < kTwo63) {
        return mixHash(static_cast<uint64_t>(static_cast<int64_t>(d)));
      }
      uint64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      return mixHash(bits ^ 0x9e3779b97f4a7c15ull);
    }
    case Kind::String:
      return v.stringObject()->hash();
    case Kind::Tuple: {
      DepthGuard guard;
      uint64_t h = 0x345678;
      for (const Value& item : v.list().items()) h = (h ^ hashOf(item)) * 1000003;
      return mixHash(h);
    }
    case Kind::List:
    case Kind::Dict:
      fail("unhashable type: `" + std::string(typeName(v)) + "`");
    case Kind::Object:
      return mixHash(reinterpret_cast<uintptr_t>(v.object()));
  }
  return 0;
}

std::string_view binOpSymbol(BinOp op) {
  switch (op) {
    case BinOp::Add:
      return "+";
    case BinOp::Sub:
      return "-";
    case BinOp::Mul:
      return "*";
    case BinOp::Div:
      return "/";
    case BinOp::FloorDiv:
      return "//";
    case BinOp::Mod:
      return "%";
    case BinOp::Pow:
      return "**";
  }
  return "?";
}

Value binary(BinOp op, const Value& a, const Value& b) {
  checkDefined(a, b);
  switch (op) {
    case BinOp::Add:
      return add(a, b);
    case BinOp::Sub:
      if (!a.isNumber() || !b.isNumber()) failOperands(op, a, b);
      if (a.isFloat() || b.isFloat()) return Value::real(a.number() - b.number());
      return Value::integer(subInts(a.integral(), b.integral()));
    case BinOp::Mul:
      return multiply(a, b);
    case BinOp::Div:
    case BinOp::FloorDiv:
    case BinOp::Mod:
      return divideLike(op, a, b);
    case BinOp::Pow:
      return power(a, b);
  }
  failOperands(op, a, b);
}

Value negate(const Value& v) {
  if (v.isUndefined()) failUndefined(v);
  if (v.isFloat()) return Value::real(-v.f());
  if (v.isInt() || v.isBool()) {
    if (v.integral() == std::numeric_limits<int64_t>::min()) fail("integer overflow");
    return Value::integer(-v.integral());
  }
  fail("bad operand type for unary `-`: `" + std::string(typeName(v)) + "`");
}

Value unaryPlus(const Value& v) {
  if (v.isUndefined()) failUndefined(v);
  if (v.isFloat() || v.isInt()) return v;
  if (v.isBool()) return Value::integer(v.integral());
  fail("bad operand type for unary `+`: `" + std::string(typeName(v)) + "`");
}

bool contains(const Value& container, const Value& item) {
  switch (container.kind()) {
    case Kind::String:
      if (!item.isString()) {
        if (item.isUndefined()) failUndefined(item);
        fail("`in <string>` requires a string as left operand, not `" +
             std::string(typeName(item)) + "`");
      }
      return container.s().find(item.s()) != std::string::npos;
    case Kind::List:
    case Kind::Tuple:
      for (const Value& x : container.list().items()) {
        if (equals(x, item)) return true;
      }
      return false;
    case Kind::Dict:
      return container.dict().find(item) != nullptr;
    case Kind::Undefined:
      return false;
    default: {
      for (const Value& x : iterate(container)) {
        if (equals(x, item)) return true;
      }
      return false;
    }
  }
}

bool isIterable(const Value& v) {
  switch (v.kind()) {
    case Kind::Undefined:
    case Kind::String:
    case Kind::List:
    case Kind::Tuple:
    case Kind::Dict:
      return true;
    case Kind::Object: {
      std::vector<Value> ignored;
      return v.object()->iterate(ignored);
    }
    default:
      return false;
  }
}

std::vector<Value> iterate(const Value& v) {
  std::vector<Value> out;
  switch (v.kind()) {
    case Kind::Undefined:
      return out;
    case Kind::String:
      for (size_t pos = 0; pos < v.s().size();) {
        size_t start = pos;
        unicode::decode(v.s(), pos);
        out.push_back(Value::string(v.s().substr(start, pos - start)));
      }
      return out;
    case Kind::List:
    case Kind::Tuple:
      return v.list().items();
    case Kind::Dict:
      out.reserve(v.dict().size());
      for (const auto& entry : v.dict().entries()) out.push_back(entry.first);
      return out;
    case Kind::Object:
      if (v.object()->iterate(out)) return out;
      break;
    default:
      break;
  }
  fail("`" + std::string(typeName(v)) + "` object is not iterable");
}

int64_t length(const Value& v) {
  switch (v.kind()) {
    case Kind::Undefined:
      return 0;
    case Kind::String:
      return static_cast<int64_t>(unicode::length(v.s()));
    case Kind::List:
    case Kind::Tuple:
      return static_cast<int64_t>(v.list().items().size());
    case Kind::Dict:
      return static_cast<int64_t>(v.dict().size());
    case Kind::Object: {
      std::vector<Value> items;
      if (v.object()->iterate(items)) return static_cast<int64_t>(items.size());
      break;
    }
    default:
      break;
  }
  fail("object of type `" + std::string(typeName(v)) + "` has no len()");
}

int64_t floatToInt(double d) {
  if (std::isnan(d)) fail("cannot convert float NaN to integer");
  if (std::isinf(d)) fail("cannot convert float infinity to integer");
  double t = std::trunc(d);
  if (t >= kTwo63 || t < -kTwo63) fail("integer overflow");
  return static_cast<int64_t>(t);
}

void checkSize(size_t n, std::string_view what) {
  size_t limit = what == "string" ? activeLimits().string_bytes : activeLimits().items;
  if (n > limit) fail(std::string(what) + " too large (limit " + std::to_string(limit) + ")");
}

namespace {
thread_local int value_depth = 0;
constexpr int kMaxValueDepth = 400;
}  // namespace

DepthGuard::DepthGuard() {
  if (++value_depth > kMaxValueDepth) {
    --value_depth;
    fail("maximum recursion depth exceeded");
  }
}

DepthGuard::~DepthGuard() { --value_depth; }

}  // namespace smachac::tmpl
