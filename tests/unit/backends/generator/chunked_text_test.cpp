// ChunkedText: the text is the same however its pieces fall across chunks.
#include "backends/generator/chunked_text.h"

#include <doctest/doctest.h>

#include <string>

namespace smachac::generator {
namespace {

/// `count` pieces of `size` bytes, each of its own letter.
std::string appendPieces(ChunkedText& text, size_t count, size_t size) {
  std::string expected;
  for (size_t i = 0; i < count; ++i) {
    std::string piece(size, static_cast<char>('a' + i % 26));
    text.append(piece);
    expected += piece;
  }
  return expected;
}

TEST_CASE("a small text is one string, copied or taken") {
  ChunkedText text;
  CHECK(text.empty());
  std::string expected = appendPieces(text, 3, 5);
  CHECK(text.joined() == expected);
  CHECK(text.take() == expected);
  CHECK(text.empty());
  CHECK(text.take().empty());
}

TEST_CASE("a text beyond one chunk keeps every byte in order") {
  ChunkedText text;
  std::string expected = appendPieces(text, 9000, 333);  // about 3 MB: several chunks
  expected += std::string(3 << 20, 'z');                 // a piece larger than a chunk
  text.append(std::string(3 << 20, 'z'));
  expected += appendPieces(text, 5, 7);
  CHECK(text.joined() == expected);
  CHECK(text.take() == expected);
  CHECK(text.empty());
  text.append("again");
  CHECK(text.joined() == "again");
}

}  // namespace
}  // namespace smachac::generator
