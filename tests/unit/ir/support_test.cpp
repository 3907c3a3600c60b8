// Suggestions, UTF-8 validation, source lines.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <span>
#include <string>
#include <utility>
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

namespace {

/// The whole optimal-string-alignment table, as the bounded search must agree with.
size_t fullTableDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

}  // namespace

TEST_CASE("suggestions agree with the whole distance table") {
  std::mt19937 random(7);
  auto word = [&] {
    std::string text(1 + random() % 12, 'a');
    for (char& c : text) c = static_cast<char>('a' + random() % 3);  // few letters: near misses
    return text;
  };
  std::vector<std::string> candidates;
  for (int i = 0; i < 300; ++i) candidates.push_back(word());
  for (int round = 0; round < 300; ++round) {
    const std::string query = word();
    std::vector<std::pair<size_t, std::string>> expected;
    for (const std::string& candidate : candidates) {
      const size_t distance = fullTableDistance(query, candidate);
      if (candidate != query && distance <= std::clamp<size_t>(query.size() / 3, 1, 3)) {
        expected.emplace_back(distance, candidate);
      }
    }
    std::stable_sort(expected.begin(), expected.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::string> expected_names;
    for (const auto& [distance, name] : expected) expected_names.push_back(name);
    INFO("query " << query);
    CHECK(smachac::closeMatches(query, candidates, candidates.size()) == expected_names);
    CHECK(smachac::editDistance(query, candidates[round]) ==
          fullTableDistance(query, candidates[round]));
  }
}

TEST_CASE("a suggestion budget pays for whole searches, then none") {
  const std::vector<std::string> names = {"OPEN", "CLOSE", "MOVE"};
  {
    smachac::SuggestionBudget budget(5);
    CHECK(smachac::closestMatch("OPNE", names) == "OPEN");  // 3 comparisons, 2 left
    CHECK_FALSE(smachac::closestMatch("OPNE", names).has_value());
    {
      smachac::SuggestionBudget inner(3);
      CHECK(smachac::closestMatch("CLOES", names) == "CLOSE");
    }
    CHECK(smachac::closestMatch("OPNE", std::span(names).first(2)) == "OPEN");  // the last 2
    CHECK_FALSE(smachac::closestMatch("OPNE", std::span(names).first(1)).has_value());
  }
  CHECK(smachac::closestMatch("OPNE", names) == "OPEN");  // no budget: no limit
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
  for (const auto& offset_line_column : expected) {
    const size_t offset = offset_line_column.first;  // not a binding: INFO captures it
    INFO("offset " << offset);
    smachac::SourceLoc loc = sources.locOf(f, offset, 2);
    CHECK(loc.line == offset_line_column.second.first);
    CHECK(loc.column == offset_line_column.second.second);
    CHECK(loc.length == 2);
  }
  uint32_t empty = sources.addFile("empty.yml", "");
  CHECK(sources.lineText(empty, 1).empty());
  CHECK(sources.locOf(empty, 0).line == 1);
}
