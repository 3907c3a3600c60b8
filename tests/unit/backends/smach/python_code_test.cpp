// Python source text for template values: literals, SMACHA's bare values, comments, names.
#include "backends/smach/python_code.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

namespace smachac::backends::smach {
namespace {

using tmpl::Value;

TEST_CASE("pythonLiteral is repr() except for non-finite floats, at any depth") {
  CHECK(pythonLiteral(Value::real(0.1)) == "0.1");
  CHECK(pythonLiteral(Value::boolean(true)) == "True");
  CHECK(pythonLiteral(Value::string("it's")) == "\"it's\"");
  CHECK(pythonLiteral(Value::real(std::nan(""))) == "float('nan')");
  CHECK(pythonLiteral(Value::real(-std::numeric_limits<double>::infinity())) == "-float('inf')");
  Value dict = Value::newDict();
  dict.dict().setString("k\n", Value::newList({Value::real(INFINITY), Value::none()}));
  CHECK(pythonLiteral(dict) == "{'k\\n': [float('inf'), None]}");
}

TEST_CASE("pythonCode writes SMACHA's code-like strings bare only when they compile") {
  CHECK(pythonCode(Value::string("12")) == "12");
  CHECK(pythonCode(Value::string("-1.5e-3")) == "-1.5e-3");
  CHECK(pythonCode(Value::string("geometry_msgs.msg.Point")) == "geometry_msgs.msg.Point");
  CHECK(pythonCode(Value::string("Point()")) == "Point()");
  CHECK(pythonCode(Value::string("1.2.3")) == "'1.2.3'");
  CHECK(pythonCode(Value::string("012")) == "'012'");
  CHECK(pythonCode(Value::string("nan")) == "'nan'");
  CHECK(pythonCode(Value::string(" 2 ")) == "' 2 '");
  CHECK(pythonCode(Value::string("a.if")) == "'a.if'");
  CHECK(pythonCode(Value::string("x.1")) == "'x.1'");
  CHECK(pythonCode(Value::string("f()\n")) == "'f()\\n'");
}

TEST_CASE("pythonCode writes a call bare only when the text is one call") {
  CHECK(pythonCode(Value::string("rospy.Duration(1, 'a)')")) == "rospy.Duration(1, 'a)')");
  CHECK(pythonCode(Value::string("f(g([1, 2]), {'k': (3)})")) == "f(g([1, 2]), {'k': (3)})");
  CHECK(pythonCode(Value::string("f(); import os; os.system('x')")) ==
        "\"f(); import os; os.system('x')\"");
  CHECK(pythonCode(Value::string("1); import os; os.system('x')")) ==
        "\"1); import os; os.system('x')\"");
  CHECK(pythonCode(Value::string("a + f(1)")) == "'a + f(1)'");
  CHECK(pythonCode(Value::string("f(1) + g(2)")) == "'f(1) + g(2)'");
  CHECK(pythonCode(Value::string("f(')")) == "\"f(')\"");
  CHECK(pythonCode(Value::newList({Value::real(std::nan(""))})) == "[float('nan')]");
}

TEST_CASE("pythonComment keeps a comment on its line") {
  CHECK(pythonComment("A'B\"C\\ é ✓") == "A'B\"C\\ é ✓");
  CHECK(pythonComment("S\nimport os\r\tT") == "S\\nimport os\\r\\tT");
  CHECK(pythonComment(std::string("n\0\x7f", 3)) == "n\\x00\\x7f");
  CHECK(pythonComment("nel\u0085ls\u2028") == "nel\\x85ls\\u2028");
}

TEST_CASE("identifierPart writes other bytes as _xHH") {
  CHECK(identifierPart("state_1") == "state_1");
  CHECK(identifierPart("s\nt é") == "s_x0at_x20_xc3_xa9");
}

}  // namespace
}  // namespace smachac::backends::smach
