// SourceManager: file registry and line lookup for diagnostics.
#include "ir/support/source_manager.h"

#include <algorithm>
#include <memory>

#include "ir/support/check.h"

namespace smachac {

uint32_t SourceManager::addFile(std::string path, std::string content) {
  files_.emplace_back(std::move(path), std::move(content));
  return static_cast<uint32_t>(files_.size());
}

const SourceManager::File& SourceManager::file(uint32_t id) const {
  SMACHAC_CHECK(id >= 1 && id <= files_.size(), "unknown file id");
  return files_[id - 1];
}

const std::vector<size_t>& SourceManager::lineStarts(const File& file) {
  if (const std::vector<size_t>* known = file.line_starts.load(std::memory_order_acquire)) {
    return *known;
  }
  auto starts = std::make_unique<std::vector<size_t>>(1, 0);
  const std::string& text = file.content;
  for (size_t nl = text.find('\n'); nl != std::string::npos; nl = text.find('\n', nl + 1)) {
    starts->push_back(nl + 1);
  }
  const std::vector<size_t>* expected = nullptr;
  if (file.line_starts.compare_exchange_strong(expected, starts.get(), std::memory_order_acq_rel)) {
    return *starts.release();
  }
  return *expected;  // another thread published the same starts first
}

const std::string& SourceManager::path(uint32_t id) const { return file(id).path; }

std::string_view SourceManager::content(uint32_t id) const { return file(id).content; }

std::string_view SourceManager::lineText(uint32_t id, uint32_t line) const {
  const File& f = file(id);
  const std::vector<size_t>& starts = lineStarts(f);
  line = std::max(line, 1u);
  if (line > starts.size()) return {};
  std::string_view text = f.content;
  const size_t start = starts[line - 1];
  const size_t end = line < starts.size() ? starts[line] - 1 : text.size();
  std::string_view result = text.substr(start, end - start);
  if (!result.empty() && result.back() == '\r') result.remove_suffix(1);
  return result;
}

SourceLoc SourceManager::locOf(uint32_t id, size_t offset, uint32_t length) const {
  const File& f = file(id);
  offset = std::min(offset, f.content.size());
  const std::vector<size_t>& starts = lineStarts(f);
  const auto after = std::upper_bound(starts.begin(), starts.end(), offset);
  const auto line = static_cast<uint32_t>(after - starts.begin());
  return {id, line, static_cast<uint32_t>(offset - *(after - 1) + 1), length};
}

}  // namespace smachac
