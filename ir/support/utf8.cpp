// UTF-8 validation. Runs of plain ASCII (most script text) are checked 64 bytes at a time.
#include "ir/support/utf8.h"

#include <cstdint>

namespace smachac {
size_t utf8SequenceLength(std::string_view text, size_t i) {
  auto byte = [&](size_t k) { return static_cast<uint8_t>(text[k]); };
  uint8_t lead = byte(i);
  if (lead == 0) return 0;
  if (lead < 0x80) return 1;
  size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
  if (length == 0 || lead > 0xF4 || i + length > text.size()) return 0;
  for (size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  }
  uint8_t second = byte(i + 1);
  if (lead == 0xE0 && second < 0xA0) return 0;   // overlong
  if (lead == 0xED && second >= 0xA0) return 0;  // surrogate
  if (lead == 0xF0 && second < 0x90) return 0;   // overlong
  if (lead == 0xF4 && second >= 0x90) return 0;  // beyond U+10FFFF
  return length;
}

namespace {

/// Bytes checked at once by findInvalidUtf8's fast path: a branch-free loop over a fixed
/// count, which the compiler vectorises.
constexpr size_t kAsciiChunk = 64;

/// True when the kAsciiChunk bytes at `chunk` are all ASCII and none is NUL.
bool isAsciiChunkWithoutNul(const char* chunk) {
  uint8_t odd = 0;
  for (size_t i = 0; i < kAsciiChunk; ++i) {
    auto c = static_cast<uint8_t>(chunk[i]);
    odd |= static_cast<uint8_t>(static_cast<uint8_t>(c - 1) >= 0x7F);
  }
  return odd == 0;
}

}  // namespace

std::optional<size_t> findInvalidUtf8(std::string_view text) {
  for (size_t i = 0; i < text.size();) {
    if (text.size() - i >= kAsciiChunk && isAsciiChunkWithoutNul(text.data() + i)) {
      i += kAsciiChunk;
      continue;
    }
    size_t length = utf8SequenceLength(text, i);
    if (length == 0) return i;
    i += length;
  }
  return std::nullopt;
}

}  // namespace smachac
