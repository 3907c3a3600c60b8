// Numeric filters: int, float, abs, round (Python semantics, including int('42.23') == 42).
#include <cmath>
#include <cstdio>
#include <limits>

#include "backends/tmpl/error.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/values/py_number.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::tmpl {
namespace {

using Args = const CallArgs&;

Value intFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "int", {"default", "base"});
  Value fallback = b.get(0, Value::integer(0));
  if (in.isUndefined()) fail(in.undefinedMessage());
  if (in.isInt()) return in;
  if (in.isBool()) return Value::integer(in.integral());
  if (in.isFloat()) {
    if (std::isnan(in.f())) return fallback;
    return Value::integer(floatToInt(in.f()));
  }
  if (!in.isString()) return fallback;
  int64_t value = 0;
  bool overflow = false;
  if (parsePythonInt(in.s(), static_cast<int>(b.getInt(1, 10)), value, overflow))
    return Value::integer(value);
  if (overflow) fail("integer overflow");
  double d = 0;
  if (!parsePythonFloat(in.s(), d) || std::isnan(d)) return fallback;
  return Value::integer(floatToInt(d));
}

Value floatFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "float", {"default"});
  Value fallback = b.get(0, Value::real(0.0));
  if (in.isUndefined()) fail(in.undefinedMessage());
  if (in.isNumber()) return Value::real(in.number());
  double d = 0;
  if (in.isString() && parsePythonFloat(in.s(), d)) return Value::real(d);
  return fallback;
}

Value absFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "abs", {});
  if (in.isFloat()) return Value::real(std::fabs(in.f()));
  if (in.isInt() || in.isBool()) {
    if (in.integral() == std::numeric_limits<int64_t>::min()) fail("integer overflow");
    return Value::integer(in.integral() < 0 ? -in.integral() : in.integral());
  }
  if (in.isUndefined()) fail(in.undefinedMessage());
  fail("bad operand type for abs(): `" + std::string(typeName(in)) + "`");
}

// Python's round(int, ndigits) for ndigits < 0: round half to even on multiples of 10^-ndigits.
int64_t roundInt(int64_t v, int64_t ndigits) {
  if (ndigits >= 0) return v;
  if (ndigits < -18) return 0;
  int64_t unit = 1;
  for (int64_t i = 0; i < -ndigits; ++i) unit *= 10;
  int64_t q = v / unit;
  int64_t r = v % unit;
  if (r < 0) {
    r += unit;
    --q;
  }
  if (2 * r > unit || (2 * r == unit && (q & 1))) ++q;
  int64_t out = 0;
  if (__builtin_mul_overflow(q, unit, &out)) fail("integer overflow");
  return out;
}

double roundFloat(double x, int64_t ndigits) {
  if (!std::isfinite(x) || ndigits > 323) return x;
  if (ndigits < -308) return 0.0 * x;
  if (ndigits >= 0) {
    char buf[400];
    std::snprintf(buf, sizeof buf, "%.*f", static_cast<int>(ndigits), x);
    return std::strtod(buf, nullptr);
  }
  double unit = std::pow(10.0, static_cast<double>(-ndigits));
  double r = std::nearbyint(x / unit) * unit;
  return r == 0.0 ? std::copysign(0.0, x) : r;
}

Value roundFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "round", {"precision", "method"});
  int64_t precision = b.getInt(0, 0);
  std::string method = b.has(1) ? str(*b.get(1)) : "common";
  if (method != "common" && method != "ceil" && method != "floor") {
    fail("method must be `common`, `ceil` or `floor`");
  }
  if (in.isUndefined()) fail(in.undefinedMessage());
  if (!in.isNumber())
    fail("type `" + std::string(typeName(in)) + "` doesn't define __round__ method");
  if (method == "common") {
    if (!in.isFloat()) return Value::integer(roundInt(in.integral(), precision));
    return Value::real(roundFloat(in.f(), precision));
  }
  double scale = std::pow(10.0, static_cast<double>(precision));
  double scaled = in.number() * scale;
  double whole = method == "ceil" ? std::ceil(scaled) : std::floor(scaled);
  return Value::real(whole / scale);
}

}  // namespace

void registerNumberFilters(BuiltinTable& r) {
  r.addFilter("int", intFilter);
  r.addFilter("float", floatFilter);
  r.addFilter("abs", absFilter);
  r.addFilter("round", roundFilter);
}

}  // namespace smachac::tmpl
