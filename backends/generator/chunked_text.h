// Text appended piece by piece and taken whole at the end: a code buffer of the generator.
// Up to 1 MiB it is one string; beyond, it grows by chunks of 1 MiB instead of doubling, so
// that a big script's code is never copied into a buffer twice its size, and `take` joins the
// chunks while freeing them: the code is never held twice.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace smachac::generator {

class ChunkedText {
 public:
  void append(std::string_view text);
  bool empty() const { return size_ == 0; }
  /// The whole text, copied.
  std::string joined() const;
  /// The whole text, moved out; the buffer is left empty.
  std::string take();

 private:
  static constexpr size_t kChunkBytes = size_t{1} << 20;
  std::vector<std::string> chunks_;
  size_t size_ = 0;
};

}  // namespace smachac::generator
