// Stored token streams (backends/tmpl/lexer/token_table.h): what the lexer makes of a source
// comes back unchanged, and words that do not fit the source given are refused.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "backends/tmpl/lexer/lexer.h"
#include "backends/tmpl/lexer/token_table.h"

namespace smachac::tmpl {
namespace {

bool same(const std::vector<Token>& a, const std::vector<Token>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].kind != b[i].kind || a[i].pos != b[i].pos || a[i].length != b[i].length) return false;
  }
  return true;
}

TEST_CASE("packed tokens unpack to what the lexer made") {
  std::string source = normalizeSource(
      "{# c #}\n  {%- macro m(x, y=1) -%}{{ x | upper ~ 'é' }}{% endmacro %}\n"
      "{% raw %}{{ raw }}{% endraw %}{{ 1.5e3 + 0x1F }}\n");
  std::vector<Token> lexed = tokenize(source);
  std::optional<std::vector<Token>> unpacked = unpackTokens(packTokens(lexed), source);
  REQUIRE(unpacked);
  CHECK(same(*unpacked, lexed));
}

TEST_CASE("words that do not fit the source are refused") {
  std::string source = "a {{ b }} c";
  std::vector<uint32_t> words = packTokens(tokenize(source));
  CHECK_FALSE(unpackTokens(words, "a {{ b }} c and more"));  // the end token is elsewhere
  CHECK_FALSE(unpackTokens(words, "a {{"));                  // tokens past the end
  CHECK_FALSE(unpackTokens({}, source));
  std::vector<uint32_t> odd(words.begin(), words.end() - 1);
  CHECK_FALSE(unpackTokens(odd, source));
  std::vector<uint32_t> bad_kind = words;
  bad_kind[0] |= 0xff;
  CHECK_FALSE(unpackTokens(bad_kind, source));
  std::vector<uint32_t> out_of_order = words;
  std::swap(out_of_order[1], out_of_order[3]);
  CHECK_FALSE(unpackTokens(out_of_order, source));
}

}  // namespace
}  // namespace smachac::tmpl
