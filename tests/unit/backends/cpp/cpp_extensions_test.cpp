// The C++ target's string literals and value expressions.
#include "backends/cpp/cpp_extensions.h"

#include <doctest/doctest.h>

#include "backends/tmpl/values/value.h"

namespace smachac::backends::cpp {
namespace {

using tmpl::Value;

TEST_CASE("cppStringLiteral escapes what C++ would read otherwise") {
  CHECK(cppStringLiteral("plain") == "\"plain\"");
  CHECK(cppStringLiteral("say \"hi\"\\") == "\"say \\\"hi\\\"\\\\\"");
  CHECK(cppStringLiteral("a\nb\tc\rd") == "\"a\\nb\\tc\\rd\"");
  CHECK(cppStringLiteral(std::string("n\0"
                                     "1",
                                     3)) == "\"n\\0001\"");
  CHECK(cppStringLiteral("\x7f\xc3\xa9") == "\"\\177\\303\\251\"");
  CHECK(cppStringLiteral("?\?/") == "\"?\\?/\"");
}

TEST_CASE("cppCommentText keeps a comment on its line and never splices the next") {
  CHECK(cppCommentText("A'B\"C */ é") == "A'B\"C */ é");
  CHECK(cppCommentText("S\nT\r") == "S\\nT\\r");
  CHECK(cppCommentText("X \\") == "X \\134");
}

TEST_CASE("a !str string is a string even in backticks") {
  Value forced = Value::string("`f(1)`");
  auto is_forced = [&forced](const Value& v) { return v.identity() == forced.identity(); };
  CHECK(cppValueExpression(forced, is_forced) == "std::string(\"`f(1)`\")");
  CHECK(cppValueExpression(Value::newList({forced}), is_forced) ==
        "rt::List{rt::Value(std::string(\"`f(1)`\"))}");
  CHECK(cppValueExpression(Value::string("`f(1)`"), is_forced) == "f(1)");
}

TEST_CASE("every byte gives a literal of plain ASCII") {
  std::string all;
  for (int c = 0; c < 256; ++c) all += static_cast<char>(c);
  std::string literal = cppStringLiteral(all);
  for (char c : literal) {
    auto byte = static_cast<unsigned char>(c);
    CHECK((byte >= 0x20 && byte < 0x7f));
  }
}

TEST_CASE("cppValueExpression writes runtime values") {
  CHECK(cppValueExpression(Value::none()) == "nullptr");
  CHECK(cppValueExpression(Value::boolean(true)) == "true");
  CHECK(cppValueExpression(Value::integer(-3)) == "int64_t{-3}");
  CHECK(cppValueExpression(Value::integer(INT64_MIN)) == "int64_t{-9223372036854775807 - 1}");
  CHECK(cppValueExpression(Value::real(0.1)) == "double{0.1}");
  CHECK(cppValueExpression(Value::real(2.0)) == "double{2.0}");
  CHECK(cppValueExpression(Value::real(1e300)) == "double{1e+300}");
  CHECK(cppValueExpression(Value::string("x")) == "std::string(\"x\")");
  CHECK(cppValueExpression(Value::string("`f(1)`")) == "f(1)");
  CHECK(cppValueExpression(Value::newList({Value::integer(1), Value::string("a")})) ==
        "rt::List{rt::Value(int64_t{1}), rt::Value(std::string(\"a\"))}");
  CHECK(cppValueExpression(Value::newList()) == "rt::List{}");
}

TEST_CASE("cppUserdataArgument writes plain strings as bare literals, the rest as cppvalue") {
  Value forced = Value::string("`f(1)`");
  auto is_forced = [&forced](const Value& v) { return v.identity() == forced.identity(); };
  CHECK(cppUserdataArgument(Value::string("a \"b\""), is_forced) == "\"a \\\"b\\\"\"");
  CHECK(cppUserdataArgument(forced, is_forced) == "\"`f(1)`\"");
  CHECK(cppUserdataArgument(Value::string("`f(1)`"), is_forced) == "f(1)");
  CHECK(cppUserdataArgument(Value::string(std::string("a\0b", 3)), is_forced) ==
        "std::string(\"a\\000b\", 3)");
  CHECK(cppUserdataArgument(Value::integer(2), is_forced) == "int64_t{2}");
  CHECK(cppUserdataArgument(Value::none(), is_forced) == "nullptr");
  CHECK(cppUserdataArgument(Value::newList({Value::string("a")}), is_forced) ==
        "rt::List{rt::Value(std::string(\"a\"))}");
}

}  // namespace
}  // namespace smachac::backends::cpp
