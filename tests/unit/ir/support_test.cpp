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
