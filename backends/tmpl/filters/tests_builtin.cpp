// Built-in tests: defined, undefined, none, string, number, integer, float, boolean, mapping,
// sequence, iterable, callable, sameas, eq/equalto, ne, lt, le, gt, ge, in, true, false,
// lower, upper, divisibleby, even, odd, escaped, filter, test.
#include "backends/tmpl/error.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/renderer/runtime.h"
#include "backends/tmpl/values/string_ops.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::tmpl {
namespace {

using Args = const CallArgs&;

const Value& operand(Args args, std::string_view test) {
  ArgBinder b(args, test, {"other"});
  return b.require(0);
}

void noArgs(Args args, std::string_view test) { ArgBinder(args, test, {}); }

bool definedTest(Exec&, const Value& v, Args a) { return noArgs(a, "defined"), !v.isUndefined(); }
bool undefinedTest(Exec&, const Value& v, Args a) {
  return noArgs(a, "undefined"), v.isUndefined();
}
bool noneTest(Exec&, const Value& v, Args a) { return noArgs(a, "none"), v.isNone(); }
bool stringTest(Exec&, const Value& v, Args a) { return noArgs(a, "string"), v.isString(); }
bool numberTest(Exec&, const Value& v, Args a) { return noArgs(a, "number"), v.isNumber(); }
bool integerTest(Exec&, const Value& v, Args a) { return noArgs(a, "integer"), v.isInt(); }
bool floatTest(Exec&, const Value& v, Args a) { return noArgs(a, "float"), v.isFloat(); }
bool booleanTest(Exec&, const Value& v, Args a) { return noArgs(a, "boolean"), v.isBool(); }
bool trueTest(Exec&, const Value& v, Args a) { return noArgs(a, "true"), v.isBool() && v.b(); }
bool falseTest(Exec&, const Value& v, Args a) { return noArgs(a, "false"), v.isBool() && !v.b(); }
bool mappingTest(Exec&, const Value& v, Args a) { return noArgs(a, "mapping"), v.isDict(); }
bool iterableTest(Exec&, const Value& v, Args a) { return noArgs(a, "iterable"), isIterable(v); }
bool escapedTest(Exec&, const Value& v, Args a) { return noArgs(a, "escaped"), v.isMarkup(); }

bool sequenceTest(Exec&, const Value& v, Args a) {
  noArgs(a, "sequence");
  return v.isUndefined() || v.isString() || v.isListOrTuple() || v.isDict();
}

bool callableTest(Exec&, const Value& v, Args a) {
  noArgs(a, "callable");
  return v.isUndefined() || (v.isObject() && v.object()->isCallable());
}

bool sameasTest(Exec&, const Value& v, Args a) {
  const Value& other = operand(a, "sameas");
  if (v.kind() != other.kind()) return false;
  switch (v.kind()) {
    case Kind::None:
      return true;
    case Kind::Bool:
      return v.b() == other.b();
    case Kind::Int:
      return v.i() == other.i() && v.i() >= -5 && v.i() <= 256;
    case Kind::Undefined:
    case Kind::Float:
      return false;
    default:
      return v.identity() == other.identity();
  }
}

bool eqTest(Exec&, const Value& v, Args a) { return equals(v, operand(a, "eq")); }
bool neTest(Exec&, const Value& v, Args a) { return !equals(v, operand(a, "ne")); }
bool ltTest(Exec&, const Value& v, Args a) { return lessThan(v, operand(a, "lt")); }
bool gtTest(Exec&, const Value& v, Args a) { return lessThan(operand(a, "gt"), v); }
bool leTest(Exec&, const Value& v, Args a) {
  const Value& o = operand(a, "le");
  return lessThan(v, o) || equals(v, o);
}
bool geTest(Exec&, const Value& v, Args a) {
  const Value& o = operand(a, "ge");
  return lessThan(o, v) || equals(v, o);
}
bool inTest(Exec&, const Value& v, Args a) { return contains(operand(a, "in"), v); }

bool lowerTest(Exec&, const Value& v, Args a) {
  noArgs(a, "lower");
  CallArgs none;
  return truthy(stringMethod(Value::string(str(v)), "islower", none));
}

bool upperTest(Exec&, const Value& v, Args a) {
  noArgs(a, "upper");
  CallArgs none;
  return truthy(stringMethod(Value::string(str(v)), "isupper", none));
}

bool modEquals(const Value& v, const Value& divisor, int64_t expected) {
  return equals(binary(BinOp::Mod, v, divisor), Value::integer(expected));
}

bool divisiblebyTest(Exec&, const Value& v, Args a) {
  ArgBinder b(a, "divisibleby", {"num"});
  return modEquals(v, b.require(0), 0);
}
bool evenTest(Exec&, const Value& v, Args a) {
  return noArgs(a, "even"), modEquals(v, Value::integer(2), 0);
}
bool oddTest(Exec&, const Value& v, Args a) {
  return noArgs(a, "odd"), modEquals(v, Value::integer(2), 1);
}

bool filterTest(Exec& ex, const Value& v, Args a) {
  noArgs(a, "filter");
  return v.isString() && ex.registry.filter(v.s()) != nullptr;
}

bool testTest(Exec& ex, const Value& v, Args a) {
  noArgs(a, "test");
  return v.isString() && ex.registry.test(v.s()) != nullptr;
}

}  // namespace

void registerBuiltinTests(BuiltinTable& r) {
  r.addTest("defined", definedTest);
  r.addTest("undefined", undefinedTest);
  r.addTest("none", noneTest);
  r.addTest("string", stringTest);
  r.addTest("number", numberTest);
  r.addTest("integer", integerTest);
  r.addTest("float", floatTest);
  r.addTest("boolean", booleanTest);
  r.addTest("true", trueTest);
  r.addTest("false", falseTest);
  r.addTest("mapping", mappingTest);
  r.addTest("sequence", sequenceTest);
  r.addTest("iterable", iterableTest);
  r.addTest("callable", callableTest);
  r.addTest("sameas", sameasTest);
  r.addTest("escaped", escapedTest);
  r.addTest("eq", eqTest);
  r.addTest("equalto", eqTest);
  r.addTest("ne", neTest);
  r.addTest("lt", ltTest);
  r.addTest("lessthan", ltTest);
  r.addTest("le", leTest);
  r.addTest("gt", gtTest);
  r.addTest("greaterthan", gtTest);
  r.addTest("ge", geTest);
  r.addTest("in", inTest);
  r.addTest("lower", lowerTest);
  r.addTest("upper", upperTest);
  r.addTest("divisibleby", divisiblebyTest);
  r.addTest("even", evenTest);
  r.addTest("odd", oddTest);
  r.addTest("filter", filterTest);
  r.addTest("test", testTest);
}

}  // namespace smachac::tmpl
