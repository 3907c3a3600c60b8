// Owns the text of every file the compiler reads (scripts, sub-scripts), so that diagnostics
// can quote source lines and IR locations can be printed as path:line:col. A file's line
// starts are found once, on the first question about a line (a script with thousands of
// diagnostics asked each time from its start, which took minutes at 100,000 states); the
// const questions may be asked from several threads at once.
#pragma once

#include <atomic>
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ir/support/source_loc.h"

namespace smachac {

class SourceManager {
 public:
  /// Registers a file and returns its id (ids start at 1). `path` is shown as given.
  uint32_t addFile(std::string path, std::string content);

  const std::string& path(uint32_t id) const;
  std::string_view content(uint32_t id) const;
  /// The text of a 1-based line without its line break (line 0 is read as line 1); empty when
  /// out of range.
  std::string_view lineText(uint32_t id, uint32_t line) const;
  /// The location of a byte offset (1-based line and column).
  SourceLoc locOf(uint32_t id, size_t offset, uint32_t length = 1) const;
  size_t fileCount() const { return files_.size(); }

 private:
  struct File {
    File(std::string file_path, std::string file_content)
        : path(std::move(file_path)), content(std::move(file_content)) {}
    File(const File&) = delete;
    File& operator=(const File&) = delete;
    ~File() { delete line_starts.load(); }

    std::string path;
    std::string content;
    /// Where each line begins (0 first), once asked for; published with a compare-exchange.
    mutable std::atomic<const std::vector<size_t>*> line_starts{nullptr};
  };
  const File& file(uint32_t id) const;
  static const std::vector<size_t>& lineStarts(const File& file);

  std::deque<File> files_;
};

}  // namespace smachac
