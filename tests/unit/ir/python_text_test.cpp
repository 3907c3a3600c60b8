// Python float repr and str()/repr() of values: SMACHA scripts print values this way.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "ir/python_text.h"
#include "ir/support/python_float.h"
#include "ir/support/python_text.h"

using smachac::pythonFloatRepr;
using smachac::ir::Value;

TEST_CASE("floats print like Python's repr") {
  CHECK(pythonFloatRepr(100.0) == "100.0");
  CHECK(pythonFloatRepr(-0.08) == "-0.08");
  CHECK(pythonFloatRepr(1e-05) == "1e-05");
  CHECK(pythonFloatRepr(0.0001) == "0.0001");
  CHECK(pythonFloatRepr(0.1 + 0.2) == "0.30000000000000004");
  CHECK(pythonFloatRepr(1e16) == "1e+16");
  CHECK(pythonFloatRepr(9999999999999998.0) == "9999999999999998.0");
  CHECK(pythonFloatRepr(1.5e16) == "1.5e+16");
  CHECK(pythonFloatRepr(123456789.125) == "123456789.125");
  CHECK(pythonFloatRepr(1e100) == "1e+100");
  CHECK(pythonFloatRepr(2.5e-7) == "2.5e-07");
  CHECK(pythonFloatRepr(5e-324) == "5e-324");
  CHECK(pythonFloatRepr(1.7976931348623157e308) == "1.7976931348623157e+308");
  CHECK(pythonFloatRepr(-0.0) == "-0.0");
  CHECK(pythonFloatRepr(0.0) == "0.0");
  CHECK(pythonFloatRepr(std::numeric_limits<double>::infinity()) == "inf");
  CHECK(pythonFloatRepr(-std::numeric_limits<double>::infinity()) == "-inf");
  CHECK(pythonFloatRepr(std::nan("")) == "nan");
}

TEST_CASE("str and repr of values follow Python") {
  Value list = Value::list({Value::string("it's"), Value::string("a\"b"), Value::string("x'y\"z"),
                            Value::real(0.5), Value::boolean(true), Value::null()});
  CHECK(smachac::ir::pythonRepr(list) == R"(["it's", 'a"b', 'x\'y"z', 0.5, True, None])");
  CHECK(smachac::ir::pythonStr(Value::string("plain")) == "plain");
  CHECK(smachac::ir::pythonStr(Value::integer(-3)) == "-3");
  Value map = Value::map({{"k", {}, Value::list({Value::integer(1)})}});
  CHECK(smachac::ir::pythonStr(map) == "{'k': [1]}");
  CHECK(smachac::pythonStringRepr("tab\tnew\nline\\") == R"('tab\tnew\nline\\')");
}

TEST_CASE("repr escapes what Python does not print, as CPython does") {
  // U+00A0 (no-break space), U+2028 (line separator), U+0085, U+FEFF, an invalid byte.
  CHECK(smachac::pythonStringRepr("a\u00a0b") == R"('a\xa0b')");
  CHECK(smachac::pythonStringRepr("\u2028\u0085\ufeff") == R"('\u2028\x85\ufeff')");
  CHECK(smachac::pythonStringRepr("\xff") == R"('\udcff')");
  CHECK(smachac::pythonStringRepr("é😀\x7f") == R"('é😀\x7f')");
  CHECK(smachac::pythonStringRepr("it's") == R"("it's")");
  CHECK(smachac::pythonStringRepr("'\"") == R"('\'"')");
  Value list = Value::list({Value::string("a\u00a0b")});
  CHECK(smachac::ir::pythonStr(list) == R"(['a\xa0b'])");
}
