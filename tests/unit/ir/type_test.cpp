// Literal types and their joins.
#include <doctest/doctest.h>

#include "ir/type.h"

using smachac::ir::Type;
using smachac::ir::Value;

TEST_CASE("types of literals") {
  CHECK(Type::ofValue(Value::integer(1)).str() == "int");
  CHECK(Type::ofValue(Value::list({Value::integer(1), Value::real(2.0)})).str() == "list<float>");
  CHECK(Type::ofValue(Value::list({Value::integer(1), Value::string("a")})).str() == "list<any>");
  CHECK(Type::ofValue(Value::list({})).str() == "list<any>");
  Value nested = Value::list({Value::list({Value::real(0.1)}), Value::list({Value::integer(0)})});
  CHECK(Type::ofValue(nested).str() == "list<list<float>>");
  Value map = Value::map({{"a", {}, Value::string("x")}, {"b", {}, Value::string("y")}});
  CHECK(Type::ofValue(map).str() == "map<string, string>");
  CHECK(Type::ofValue(Value::expression("f()")).str() == "expr");
}

TEST_CASE("joins") {
  Type i = Type::of(Type::Kind::Int);
  Type f = Type::of(Type::Kind::Float);
  Type s = Type::of(Type::Kind::String);
  CHECK(Type::join(i, f) == f);
  CHECK(Type::join(i, i) == i);
  CHECK(Type::join(i, s) == Type::any());
  CHECK(Type::join(Type::listOf(i), Type::listOf(f)) == Type::listOf(f));
}
