// Suggestions, UTF-8 validation, source lines.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "ir/support/source_manager.h"
#include "ir/support/suggest.h"
#include "ir/support/utf8.h"

using namespace std::string_literals;

TEST_CASE("did you mean") {
  std::vector<std::string> names = {"OPEN", "CLOSE", "MOVE_TO_START"};
  CHECK(smachac::didYouMean("OPNE", names) == "; did you mean `OPEN`?");
  CHECK(smachac::didYouMean("MOVE_TO_STRAT", names) == "; did you mean `MOVE_TO_START`?");
  CHECK(smachac::didYouMean("WHATEVER", names).empty());
  CHECK(smachac::didYouMean("OPEN", names).empty());
  CHECK(smachac::editDistance("kitten", "sitting") == 3);
}

TEST_CASE("utf-8 validation") {
  CHECK_FALSE(smachac::findInvalidUtf8("héllo ✓ 😀").has_value());
  CHECK(smachac::findInvalidUtf8("ab\xff") == 2u);
  CHECK(smachac::findInvalidUtf8("a\0b"s) == 1u);
  CHECK(smachac::findInvalidUtf8("\xc0\xaf") == 0u);       // overlong
  CHECK(smachac::findInvalidUtf8("x\xed\xa0\x80") == 1u);  // surrogate
  CHECK(smachac::findInvalidUtf8("\xe2\x82") == 0u);       // truncated
  // Past and inside the 64-byte chunks that are checked at once.
  std::string ascii(200, 'a');
  CHECK_FALSE(smachac::findInvalidUtf8(ascii).has_value());
  for (size_t at : {0u, 63u, 64u, 130u, 199u}) {
    std::string bad = ascii;
    bad[at] = '\0';
    CHECK(smachac::findInvalidUtf8(bad) == at);
    bad[at] = '\x80';
    CHECK(smachac::findInvalidUtf8(bad) == at);
    bad[at] = '\x7f';
    CHECK_FALSE(smachac::findInvalidUtf8(bad).has_value());
  }
  CHECK_FALSE(smachac::findInvalidUtf8(std::string(70, 'a') + "\xc3\xa9" + ascii).has_value());
}

TEST_CASE("source lines and offsets") {
  smachac::SourceManager sources;
  uint32_t f = sources.addFile("a.yml", "one\r\ntwo\nthree");
  CHECK(sources.lineText(f, 1) == "one");
  CHECK(sources.lineText(f, 3) == "three");
  CHECK(sources.lineText(f, 4).empty());
  smachac::SourceLoc loc = sources.locOf(f, 9);
  CHECK(loc.line == 3);
  CHECK(loc.column == 1);
}

TEST_CASE("source lines at the edges: a line break's own offset, the end, empty lines") {
  smachac::SourceManager sources;
  uint32_t f = sources.addFile("b.yml", "ab\n\nc\n");
  CHECK(sources.lineText(f, 0) == "ab");  // line 0 reads as line 1
  CHECK(sources.lineText(f, 2).empty());
  CHECK(sources.lineText(f, 3) == "c");
  CHECK(sources.lineText(f, 4).empty());  // after the last line break
  CHECK(sources.lineText(f, 5).empty());
  const std::pair<size_t, std::pair<uint32_t, uint32_t>> expected[] = {
      {0, {1, 1}}, {2, {1, 3}}, {3, {2, 1}}, {4, {3, 1}}, {5, {3, 2}}, {6, {4, 1}}, {99, {4, 1}}};
  for (const auto& [offset, line_column] : expected) {
    INFO("offset " << offset);
    smachac::SourceLoc loc = sources.locOf(f, offset, 2);
    CHECK(loc.line == line_column.first);
    CHECK(loc.column == line_column.second);
    CHECK(loc.length == 2);
  }
  uint32_t empty = sources.addFile("empty.yml", "");
  CHECK(sources.lineText(empty, 1).empty());
  CHECK(sources.locOf(empty, 0).line == 1);
}
