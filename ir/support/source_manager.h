// Owns the text of every file the compiler reads (scripts, sub-scripts), so that diagnostics
// can quote source lines and IR locations can be printed as path:line:col.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>

#include "ir/support/source_loc.h"

namespace smachac {

class SourceManager {
 public:
  /// Registers a file and returns its id (ids start at 1). `path` is shown as given.
  uint32_t addFile(std::string path, std::string content);

  const std::string& path(uint32_t file) const;
  std::string_view content(uint32_t file) const;
  /// The text of a 1-based line without its line break; empty when out of range.
  std::string_view lineText(uint32_t file, uint32_t line) const;
  /// The location of a byte offset (1-based line and column).
  SourceLoc locOf(uint32_t file, size_t offset, uint32_t length = 1) const;
  size_t fileCount() const { return files_.size(); }

 private:
  struct File {
    std::string path;
    std::string content;
  };
  std::deque<File> files_;
};

}  // namespace smachac
