// Stored token streams (backends/tmpl/lexer/token_table.h): what the lexer makes of a source
// reads back unchanged in place, and words that do not fit the source given are refused.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "backends/tmpl/lexer/lexer.h"
#include "backends/tmpl/lexer/token_table.h"

namespace smachac::tmpl {
namespace {

bool same(std::span<const Token> a, const std::vector<Token>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].kind != b[i].kind || a[i].pos != b[i].pos || a[i].length != b[i].length) return false;
  }
  return true;
}

TEST_CASE("packed tokens read back as what the lexer made") {
  std::string source = normalizeSource(
      "{# c #}\n  {%- macro m(x, y=1) -%}{{ x | upper ~ 'é' }}{% endmacro %}\n"
      "{% raw %}{{ raw }}{% endraw %}{{ 1.5e3 + 0x1F }}\n");
  std::vector<Token> lexed = tokenize(source);
  std::vector<uint32_t> words = packTokens(lexed);
  std::optional<std::span<const Token>> stored = storedTokens(words, source);
  REQUIRE(stored);
  CHECK(stored->data() == static_cast<const void*>(words.data()));  // in place, not a copy
  CHECK(same(*stored, lexed));
}

TEST_CASE("words that do not fit the source are refused") {
  std::string source = "a {{ b }} c";
  std::vector<uint32_t> words = packTokens(tokenize(source));
  REQUIRE(storedTokens(words, source));
  CHECK_FALSE(storedTokens(words, "a {{ b }} c and more"));  // the end token is elsewhere
  CHECK_FALSE(storedTokens(words, "a {{"));                  // tokens past the end
  CHECK_FALSE(storedTokens({}, source));
  std::vector<uint32_t> short_by_one(words.begin(), words.end() - 1);
  CHECK_FALSE(storedTokens(short_by_one, source));
  std::vector<uint32_t> bad_kind = words;
  bad_kind[0] |= 0xff;
  CHECK_FALSE(storedTokens(bad_kind, source));
  std::vector<uint32_t> bad_padding = words;
  bad_padding[0] |= 0x100;  // a known kind's byte, but not zeros after it
  CHECK_FALSE(storedTokens(bad_padding, source));
  std::vector<uint32_t> out_of_order = words;
  std::swap(out_of_order[1], out_of_order[4]);
  CHECK_FALSE(storedTokens(out_of_order, source));
}

}  // namespace
}  // namespace smachac::tmpl
