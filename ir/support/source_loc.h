// A position in a source file: file id (from SourceManager), 1-based line and column, and the
// length of the span in bytes (for carets). Every IR entity and every diagnostic carries one.
#pragma once

#include <cstdint>

namespace smachac {

struct SourceLoc {
  uint32_t file = 0;  ///< 0: no file (e.g. a command-line problem)
  uint32_t line = 0;  ///< 1-based; 0: the whole file
  uint32_t column = 0;
  uint32_t length = 1;

  bool hasFile() const { return file != 0; }
  bool hasLine() const { return line != 0; }
  friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

}  // namespace smachac
