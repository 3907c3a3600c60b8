// ChunkedText: appending into the last chunk, joining on the way out.
#include "backends/generator/chunked_text.h"

#include <algorithm>
#include <utility>

namespace smachac::generator {

void ChunkedText::append(std::string_view text) {
  if (chunks_.empty()) {
    chunks_.emplace_back();
  } else if (chunks_.back().size() + text.size() > kChunkBytes) {
    chunks_.emplace_back().reserve(std::max(kChunkBytes, text.size()));
  }
  chunks_.back().append(text);
  size_ += text.size();
}

std::string ChunkedText::joined() const {
  if (chunks_.size() == 1) return chunks_.front();
  std::string out;
  out.reserve(size_);
  for (const std::string& chunk : chunks_) out += chunk;
  return out;
}

std::string ChunkedText::take() {
  std::string out;
  if (chunks_.size() == 1) {
    out = std::move(chunks_.front());
  } else {
    out.reserve(size_);
    for (std::string& chunk : chunks_) out += std::exchange(chunk, std::string());
  }
  chunks_.clear();
  size_ = 0;
  return out;
}

}  // namespace smachac::generator
