// Portable expressions: parsing, precedence (printed back with the parentheses it needs) and
// syntax errors with their offsets.
#include <doctest/doctest.h>

#include <string>

#include "frontend/expr_parser.h"

using smachac::SourceLoc;
using smachac::frontend::ExprSyntaxError;
using smachac::frontend::parseExpr;

namespace {

auto parsed(const std::string& text) {
  return parseExpr(text, [](uint32_t offset, uint32_t length) {
    return SourceLoc{1, 1, offset + 1, length};
  });
}

std::string reprinted(const std::string& text) {
  auto result = parsed(text);
  if (auto* error = std::get_if<ExprSyntaxError>(&result)) return "error: " + error->message;
  return smachac::ir::printExpr(
      std::get<std::shared_ptr<const smachac::ir::PortableExpr>>(result)->root);
}

std::string errorAt(const std::string& text) {
  auto result = parsed(text);
  auto* error = std::get_if<ExprSyntaxError>(&result);
  if (!error) return "no error";
  return std::to_string(error->offset) + ":" + std::to_string(error->length) + " " + error->message;
}

}  // namespace

TEST_CASE("precedence is Python's, parentheses only where needed") {
  CHECK(reprinted("a + b * c") == "a + b * c");
  CHECK(reprinted("(a + b) * c") == "(a + b) * c");
  CHECK(reprinted("(a - b) - c") == "a - b - c");
  CHECK(reprinted("a - (b - c)") == "a - (b - c)");
  CHECK(reprinted("a // b % c / d") == "a // b % c / d");
  CHECK(reprinted("-(a + b)") == "-(a + b)");
  CHECK(reprinted("- -a") == "--a");
  CHECK(reprinted("not a == b") == "not a == b");
  CHECK(reprinted("(not a) == b") == "(not a) == b");
  CHECK(reprinted("a or b and c") == "a or b and c");
  CHECK(reprinted("(a or b) and c") == "(a or b) and c");
  CHECK(reprinted("not (a and b)") == "not (a and b)");
  CHECK(reprinted("a if b else c if d else e") == "a if b else c if d else e");
  CHECK(reprinted("(a if b else c) if d else e") == "(a if b else c) if d else e");
  CHECK(reprinted("(a < b) == c") == "(a < b) == c");
  CHECK(reprinted("min(a, b + 1, (c))") == "min(a, b + 1, c)");
  CHECK(reprinted("len('x') + abs(-2.50)") == "len('x') + abs(-2.5)");
}

TEST_CASE("literals") {
  CHECK(reprinted("True and False") == "True and False");
  CHECK(reprinted("1e3 + .5 + 2.") == "1000.0 + 0.5 + 2.0");
  CHECK(reprinted(R"("it's" + 'a\tb' + '\u00e9\x41')") == R"("it's" + 'a\tb' + 'éA')");
  CHECK(reprinted("0 + 00") == "0 + 0");
  CHECK(reprinted("9223372036854775807") == "9223372036854775807");
}

TEST_CASE("syntax errors stop at their token") {
  CHECK(errorAt("") == "0:1 empty expression");
  CHECK(errorAt("a +") == "3:1 expected an operand, found the end of the expression");
  CHECK(errorAt("(a") == "2:1 expected `)`, found the end of the expression");
  CHECK(errorAt("a b") == "2:1 expected an operator or the end, found `b`");
  CHECK(errorAt("a = b") == "2:1 `=` assigns nothing here: compare with `==`");
  CHECK(errorAt("a < b < c") == "6:1 comparisons do not chain: write `a < b and b < c`");
  CHECK(errorAt("f(a b)") == "4:1 expected `,` or `)`, found `b`");
  CHECK(errorAt("None") == "0:4 `None` is not part of the expression language");
  CHECK(errorAt("lambda x: x") == "0:6 `lambda` is not part of the expression language");
  CHECK(errorAt("a $ b") == "2:1 unexpected character `$`");
  CHECK(errorAt("a ** 2") == "3:1 expected an operand, found `*`");
  CHECK(errorAt("'abc") == "0:4 string not closed on its line");
  CHECK(errorAt(R"('\x4')") == R"(1:3 `\x` needs 2 hex digits)");
  CHECK(errorAt(R"('\ud800')") == "1:6 a surrogate code point is no character");
  CHECK(errorAt("012") ==
        "0:3 `012`: integers do not start with 0 (Python reads no octal this way)");
  CHECK(errorAt("9223372036854775808") ==
        "0:19 integer `9223372036854775808` does not fit in 64 bits");
  CHECK(errorAt("1x") == "0:2 `1x` is not a number");
  CHECK(errorAt(std::string(300, '(') + "a" + std::string(300, ')')).find("nested too deeply") !=
        std::string::npos);
}
