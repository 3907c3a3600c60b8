// pythonExpressionError against python_expression_cases.txt: each line is `ok` or `error`, a
// tab, and code (`{NL}` for a line break), labelled by CPython's ast.parse(code, mode="eval")
// (the ctest diff/python-expression-cases checks every label against Debian's python3).
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "backends/smach/python_expression.h"

namespace smachac::backends {
namespace {

std::string withLineBreaks(std::string code) {
  for (size_t at = code.find("{NL}"); at != std::string::npos; at = code.find("{NL}", at)) {
    code.replace(at, 4, "\n");
  }
  return code;
}

TEST_CASE("every case is recognised as CPython does") {
  std::ifstream cases(SMACHAC_PYTHON_EXPRESSION_CASES);
  REQUIRE(cases.good());
  std::string line;
  int count = 0;
  while (std::getline(cases, line)) {
    const size_t tab = line.find('\t');
    REQUIRE(tab != std::string::npos);
    const std::string code = withLineBreaks(line.substr(tab + 1));
    const auto error = pythonExpressionError(code);
    INFO(line.substr(tab + 1), ": ", error ? error->message : std::string("no error"));
    CHECK((line.substr(0, tab) == "ok") == !error.has_value());
    ++count;
  }
  CHECK(count > 150);
}

TEST_CASE("errors say what and where") {
  auto error = pythonExpressionError("lambda ud: ud.x)");
  REQUIRE(error);
  CHECK(error->offset == 15);
  CHECK(error->message == "unmatched `)`");
  error = pythonExpressionError("lambda ud: ud.counter +");
  REQUIRE(error);
  CHECK(error->message == "unexpected end of the code");
  CHECK(error->offset == 23);
  error = pythonExpressionError("f(a=)");
  REQUIRE(error);
  CHECK(error->message == "unexpected `)`");
  CHECK(error->offset == 4);
  error = pythonExpressionError("'open");
  REQUIRE(error);
  CHECK(error->message == "unterminated string");
  CHECK(pythonExpressionError(std::string(100000, '(')).has_value());
  CHECK(pythonExpressionError(std::string(100000, '-') + "1").has_value());
}

}  // namespace
}  // namespace smachac::backends
