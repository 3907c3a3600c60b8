// YAML 1.2 core-schema scalar resolution.
#include <doctest/doctest.h>

#include "frontend/scalar.h"
#include "ir/value_text.h"

using smachac::frontend::resolveScalar;
using smachac::frontend::ScalarStyle;

static std::string plain(const char* text, const char* tag = "?") {
  return smachac::ir::formatValue(resolveScalar(text, ScalarStyle::Plain, tag, {}).value);
}

TEST_CASE("plain scalars") {
  CHECK(plain("yes") == "\"yes\"");
  CHECK(plain("off") == "\"off\"");
  CHECK(plain("True") == "true");
  CHECK(plain("FALSE") == "false");
  CHECK(plain("~") == "null");
  CHECK(plain("") == "null");
  CHECK(plain("0o17") == "15");
  CHECK(plain("0x1F") == "31");
  CHECK(plain("+5") == "5");
  CHECK(plain("-0.08000") == "-0.08");
  CHECK(plain(".5") == "0.5");
  CHECK(plain("1e3") == "1000.0");
  CHECK(plain("1.") == "1.0");
  CHECK(plain("-.inf") == "-inf");
  CHECK(plain(".NaN") == "nan");
  CHECK(plain("1_000") == "\"1_000\"");
  CHECK(plain("1e") == "\"1e\"");
  CHECK(plain("0x") == "\"0x\"");
  CHECK(plain("3", "!str") == "!str \"3\"");
  CHECK(plain("`f(x)`") == "`f(x)`");
}

TEST_CASE("quoted scalars stay strings") {
  auto quoted = [](const char* text) {
    return smachac::ir::formatValue(resolveScalar(text, ScalarStyle::Quoted, "!", {}).value);
  };
  CHECK(quoted("12") == "\"12\"");
  CHECK(quoted("null") == "\"null\"");
  CHECK(quoted("`lambda ud: 1`") == "`lambda ud: 1`");
}

TEST_CASE("integer overflow is reported") {
  CHECK(resolveScalar("9223372036854775807", ScalarStyle::Plain, "?", {}).int_overflow == false);
  CHECK(resolveScalar("-9223372036854775808", ScalarStyle::Plain, "?", {}).int_overflow == false);
  CHECK(resolveScalar("9223372036854775808", ScalarStyle::Plain, "?", {}).int_overflow);
  CHECK(resolveScalar("0x1ffffffffffffffff", ScalarStyle::Plain, "?", {}).int_overflow);
}
