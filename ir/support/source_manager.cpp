// SourceManager: file registry and line lookup for diagnostics.
#include "ir/support/source_manager.h"

#include "ir/support/check.h"

namespace smachac {

uint32_t SourceManager::addFile(std::string path, std::string content) {
  files_.push_back({std::move(path), std::move(content)});
  return static_cast<uint32_t>(files_.size());
}

const std::string& SourceManager::path(uint32_t file) const {
  SMACHAC_CHECK(file >= 1 && file <= files_.size(), "unknown file id");
  return files_[file - 1].path;
}

std::string_view SourceManager::content(uint32_t file) const {
  SMACHAC_CHECK(file >= 1 && file <= files_.size(), "unknown file id");
  return files_[file - 1].content;
}

std::string_view SourceManager::lineText(uint32_t file, uint32_t line) const {
  std::string_view text = content(file);
  size_t start = 0;
  for (uint32_t n = 1; n < line; ++n) {
    size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) return {};
    start = nl + 1;
  }
  size_t end = text.find('\n', start);
  std::string_view result = text.substr(start, end == std::string_view::npos ? end : end - start);
  if (!result.empty() && result.back() == '\r') result.remove_suffix(1);
  return result;
}

SourceLoc SourceManager::locOf(uint32_t file, size_t offset, uint32_t length) const {
  std::string_view text = content(file);
  if (offset > text.size()) offset = text.size();
  uint32_t line = 1;
  size_t line_start = 0;
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return {file, line, static_cast<uint32_t>(offset - line_start + 1), length};
}

}  // namespace smachac
