// Values: Python printing (str and repr), equality, ordering, hashing and reference semantics.
#include <doctest/doctest.h>

#include <cmath>

#include "backends/tmpl/values/value.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"

using smachac::tmpl::equals;
using smachac::tmpl::lessThan;
using smachac::tmpl::repr;
using smachac::tmpl::str;
using smachac::tmpl::Value;

namespace {

std::string floatRepr(double d) { return repr(Value::real(d)); }

}  // namespace

TEST_CASE("floats print as Python's shortest round-trip repr") {
  CHECK(floatRepr(100.0) == "100.0");
  CHECK(floatRepr(-0.08) == "-0.08");
  CHECK(floatRepr(1e-05) == "1e-05");
  CHECK(floatRepr(0.0001) == "0.0001");
  CHECK(floatRepr(1e16) == "1e+16");
  CHECK(floatRepr(1e15) == "1000000000000000.0");
  CHECK(floatRepr(0.1 + 0.2) == "0.30000000000000004");
  CHECK(floatRepr(1.5e300) == "1.5e+300");
  CHECK(floatRepr(2.5e-10) == "2.5e-10");
  CHECK(floatRepr(5e-324) == "5e-324");
  CHECK(floatRepr(-0.0) == "-0.0");
  CHECK(floatRepr(HUGE_VAL) == "inf");
  CHECK(floatRepr(-HUGE_VAL) == "-inf");
  CHECK(floatRepr(std::nan("")) == "nan");
  CHECK(floatRepr(123456789.125) == "123456789.125");
}

TEST_CASE("str and repr of scalars and containers") {
  CHECK(str(Value()) == "");
  CHECK(repr(Value()) == "Undefined");
  CHECK(str(Value::none()) == "None");
  CHECK(str(Value::boolean(true)) == "True");
  CHECK(str(Value::integer(-42)) == "-42");
  CHECK(str(Value::string("plain")) == "plain");
  Value list =
      Value::newList({Value::integer(1), Value::real(2.5), Value::string("x"), Value::none()});
  CHECK(str(list) == "[1, 2.5, 'x', None]");
  CHECK(str(Value::newTuple({Value::integer(1)})) == "(1,)");
  CHECK(str(Value::newTuple({})) == "()");
  Value dict = Value::newDict();
  dict.dict().setString("a", list);
  dict.dict().set(Value::integer(2), Value::newDict());
  CHECK(str(dict) == "{'a': [1, 2.5, 'x', None], 2: {}}");
}

TEST_CASE("strings are quoted and escaped like Python's repr") {
  CHECK(repr(Value::string("it's")) == "\"it's\"");
  CHECK(repr(Value::string("say \"hi\"")) == "'say \"hi\"'");
  CHECK(repr(Value::string("both ' and \"")) == "'both \\' and \"'");
  CHECK(repr(Value::string("a\\b\n\t\r")) == "'a\\\\b\\n\\t\\r'");
  CHECK(repr(Value::string(std::string("nul\0x", 5))) == "'nul\\x00x'");
  CHECK(repr(Value::string("\x7f\x1b")) == "'\\x7f\\x1b'");
  CHECK(repr(Value::string("héllo 日本 😀")) == "'héllo 日本 😀'");
  CHECK(repr(Value::string("\u00a0\u2028\u200b")) == "'\\xa0\\u2028\\u200b'");
  CHECK(repr(Value::string("\xff")) == "'\\udcff'");
  CHECK(repr(Value::string("<b>", true)) == "Markup('<b>')");
}

TEST_CASE("self-referential containers print like Python") {
  Value list = Value::newList({Value::integer(1)});
  list.list().items().push_back(list);
  CHECK(str(list) == "[1, [...]]");
  list.list().items().clear();  // break the cycle
}

TEST_CASE("equality follows Python") {
  CHECK(equals(Value::integer(1), Value::real(1.0)));
  CHECK(equals(Value::integer(1), Value::boolean(true)));
  CHECK_FALSE(equals(Value::integer(9007199254740993), Value::real(9007199254740992.0)));
  CHECK_FALSE(equals(Value::newList({Value::integer(1)}), Value::newTuple({Value::integer(1)})));
  CHECK(equals(Value(), Value()));
  CHECK_FALSE(equals(Value(), Value::none()));
  CHECK_FALSE(equals(Value::real(std::nan("")), Value::real(std::nan(""))));
  Value a = Value::newDict();
  Value b = Value::newDict();
  a.dict().setString("x", Value::integer(1));
  a.dict().setString("y", Value::integer(2));
  b.dict().setString("y", Value::real(2.0));
  b.dict().setString("x", Value::boolean(true));
  CHECK(equals(a, b));
}

TEST_CASE("ordering follows Python, with errors for mixed types") {
  CHECK(lessThan(Value::string("B"), Value::string("a")));
  CHECK(lessThan(Value::string("_x"), Value::string("a")));
  CHECK(lessThan(Value::integer(1), Value::real(1.5)));
  CHECK(lessThan(Value::newTuple({Value::integer(1), Value::string("b")}),
                 Value::newTuple({Value::integer(1), Value::string("c")})));
  CHECK(lessThan(Value::newList({Value::integer(1)}),
                 Value::newList({Value::integer(1), Value::integer(0)})));
  CHECK_THROWS_WITH(lessThan(Value::string("a"), Value::integer(1)),
                    "`<` is not supported between instances of `str` and `int`");
  CHECK_THROWS_WITH(lessThan(Value::none(), Value::none()),
                    "`<` is not supported between instances of `NoneType` and `NoneType`");
}

TEST_CASE("dict keys: 1, 1.0 and True are one key; insertion order is kept") {
  Value d = Value::newDict();
  d.dict().set(Value::integer(1), Value::string("int"));
  d.dict().set(Value::real(1.0), Value::string("float"));
  d.dict().set(Value::boolean(true), Value::string("bool"));
  d.dict().setString("b", Value::none());
  d.dict().setString("a", Value::none());
  CHECK(str(d) == "{1: 'bool', 'b': None, 'a': None}");
  for (int i = 0; i < 100; ++i) d.dict().set(Value::integer(i + 10), Value::integer(i));
  CHECK(d.dict().size() == 103);
  CHECK(str(*d.dict().find(Value::real(60.0))) == "50");
  CHECK(d.dict().findString("a") != nullptr);
  CHECK(d.dict().erase(Value::string("a")));
  CHECK(d.dict().findString("a") == nullptr);
  CHECK(str(*d.dict().find(Value::integer(109))) == "99");
  CHECK_THROWS_WITH(d.dict().set(Value::newList(), Value::none()), "unhashable type: `list`");
}

TEST_CASE("dict update replaces same keys in place and appends new ones in order") {
  Value to = Value::newDict();
  to.dict().setString("a", Value::integer(1));
  to.dict().set(Value::integer(1), Value::string("int"));
  to.dict().setString("b", Value::integer(2));
  Value from = Value::newDict();
  from.dict().setString("c", Value::integer(3));
  from.dict().set(Value::boolean(true), Value::string("bool"));  // the key 1 already there
  from.dict().setString("a", Value::integer(4));
  for (int i = 0; i < 20; ++i) from.dict().set(Value::integer(i + 10), Value::integer(i));
  to.dict().update(from.dict());
  CHECK(to.dict().size() == 24);
  CHECK(str(*to.dict().findString("a")) == "4");
  CHECK(str(*to.dict().find(Value::real(1.0))) == "bool");
  CHECK(str(*to.dict().find(Value::integer(29))) == "19");  // found through the rebuilt index
  CHECK(str(to.dict().entries()[3].first) == "c");
  CHECK(from.dict().size() == 23);  // `from` is left as it was
}

TEST_CASE("containers have reference semantics") {
  Value list = Value::newList();
  Value alias = list;
  alias.list().items().push_back(Value::integer(7));
  CHECK(str(list) == "[7]");
  CHECK(list.identity() == alias.identity());
}

TEST_CASE("deeply nested values are freed without recursion") {
  Value v = Value::newList();
  for (int i = 0; i < 1000000; ++i) v = Value::newList({v});
  v = Value::none();  // must not overflow the stack
  CHECK(str(v) == "None");
}

TEST_CASE("printing or comparing deeply nested values is bounded") {
  Value v = Value::newList();
  Value w = Value::newList();
  for (int i = 0; i < 1000; ++i) {
    v = Value::newList({v});
    w = Value::newList({w});
  }
  CHECK_THROWS_WITH(repr(v), "maximum recursion depth exceeded");
  CHECK_THROWS_WITH(equals(v, w), "maximum recursion depth exceeded");
}
