// The numbers an image (image_format.h) is made of: LEB128 varints, bounded by their type,
// and counts no larger than the bytes left (each item takes at least one). Rules: every read is
// checked; a failure throws ImageFault, which refuses the whole image (image_reader.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace smachac::tmpl {

struct ImageFault {};

// Out of line and cold: the readers' many checks share one throw (the reader's code stays
// small, which is what a compile that runs it once pays for).
[[noreturn, gnu::cold, gnu::noinline]] inline void failImage() { throw ImageFault{}; }

class ImageBytes {
 public:
  /// Reads `image` from byte `offset` on.
  ImageBytes(std::span<const uint8_t> image, size_t offset)
      : begin_(image.data()), at_(image.data() + offset), end_(image.data() + image.size()) {}

  uint64_t num() {
    uint64_t value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      uint8_t b = byte();
      value |= uint64_t(b & 0x7f) << shift;
      if (!(b & 0x80)) return value;
    }
    failImage();
  }
  uint8_t byte() {
    if (at_ == end_) failImage();
    return *at_++;
  }
  uint16_t u16() {
    uint64_t value = num();
    if (value > 0xffff) failImage();
    return static_cast<uint16_t>(value);
  }
  uint32_t u32() {
    uint64_t value = num();
    if (value > 0xffffffffu) failImage();
    return static_cast<uint32_t>(value);
  }
  bool flag() { return byte() != 0; }
  int slot() { return static_cast<int>(u16()) - 1; }
  size_t count() {
    uint64_t value = num();
    if (value > static_cast<uint64_t>(end_ - at_)) failImage();  // each item takes a byte
    return static_cast<size_t>(value);
  }
  void skip(size_t bytes) {
    if (bytes > static_cast<size_t>(end_ - at_)) failImage();
    at_ += bytes;
  }
  /// Where the next read begins, from the image's start.
  size_t offset() const { return static_cast<size_t>(at_ - begin_); }

 private:
  const uint8_t* begin_;
  const uint8_t* at_;
  const uint8_t* end_;
};

}  // namespace smachac::tmpl
