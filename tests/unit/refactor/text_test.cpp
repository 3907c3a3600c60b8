// SourceText, EditList and flow-style writing.
#include <doctest/doctest.h>

#include "refactor/flow_text.h"
#include "refactor/source_text.h"
#include "refactor/text_edits.h"

namespace smachac::refactor {

TEST_CASE("SourceText maps loader locations and lines") {
  SourceText text("a: 1\n  # c\n\nb: [x]\n");
  CHECK(text.offsetOf({1, 2, 1, 1}) == 5);
  CHECK(text.offsetOf({1, 4, 4, 1}) == 15);
  CHECK(text.lineOf(15) == 3);
  CHECK(text.lineEnd(0) == 4);
  CHECK(text.nextLineStart(0) == 5);
  CHECK(text.indentOf(1) == 2);
  CHECK(text.isCommentLine(1));
  CHECK_FALSE(text.isContentLine(2));
  CHECK(text.isContentLine(3));
}

TEST_CASE("EditList splices edits and keeps the rest byte for byte") {
  std::string source = "abcdefghij";
  EditList edits;
  edits.replace({2, 4}, "XY");
  edits.insert(6, "+");
  edits.insert(6, "!");
  edits.erase({8, 9});
  CHECK(edits.render(source, {0, source.size()}) == "abXYef+!ghj");
  CHECK(edits.render(source, {4, 7}) == "ef+!g");
}

TEST_CASE("EditList drops edits inside a replaced range and ignores enclosing ones") {
  std::string source = "0123456789";
  EditList edits;
  edits.replace({5, 6}, "five");
  edits.erase({2, 8});
  CHECK(edits.render(source, {0, 10}) == "0189");
  CHECK(edits.render(source, {4, 7}) == "4five6");
}

TEST_CASE("EditList: an insertion at a range's end belongs to the next range, except at EOF") {
  std::string source = "abcd";
  EditList edits;
  edits.insert(2, "-");
  edits.insert(4, "!");
  CHECK(edits.render(source, {0, 2}) == "ab");
  CHECK(edits.render(source, {2, 4}) == "-cd!");
}

TEST_CASE("indentLines and dedentLines") {
  CHECK(indentLines("- a:\n\n    b\n", 2) == "  - a:\n\n      b\n");
  CHECK(dedentLines("  - a:\n    b\n c\n", 2) == "- a:\n  b\nc\n");
}

TEST_CASE("flowScalar quotes only what YAML would read differently") {
  CHECK(flowScalar("FOO_1") == "FOO_1");
  CHECK(flowScalar("it's") == "it's");
  CHECK(flowScalar("true") == "'true'");
  CHECK(flowScalar("12") == "'12'");
  CHECK(flowScalar("null") == "'null'");
  CHECK(flowScalar("") == "''");
  CHECK(flowScalar("a: b") == "'a: b'");
  CHECK(flowScalar("a, b") == "'a, b'");
  CHECK(flowScalar("#x") == "'#x'");
  CHECK(flowScalar("'q'") == "'''q'''");
  CHECK(flowScalar("two\nlines") == "\"two\\nlines\"");
}

TEST_CASE("flowValue writes values in flow style") {
  ir::Value map = ir::Value::map({
      {"n", {}, ir::Value::integer(3)},
      {"f", {}, ir::Value::real(0.5)},
      {"inf", {}, ir::Value::real(1.0 / 0.0)},
      {"b", {}, ir::Value::boolean(true)},
      {"z", {}, ir::Value::null()},
      {"e", {}, ir::Value::expression("lambda ud: 1")},
      {"l", {}, ir::Value::list({ir::Value::string("a"), ir::Value::string("no")})},
  });
  CHECK(flowValue(map) ==
        "{n: 3, f: 0.5, inf: .inf, b: true, z: null, e: '`lambda ud: 1`', l: [a, no]}");
  CHECK(flowNameList({"a", "on"}) == "[a, on]");
}

}  // namespace smachac::refactor
