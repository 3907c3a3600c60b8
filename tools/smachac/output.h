// Writing generated files atomically: the content goes to a temporary file next to the
// destination, which then takes its place (renamed over it, or exchanged with an existing
// regular file, whose old content is then removed: output.cpp says why). A failed run never
// leaves a partial file and never clobbers an existing one. A destination that exists and is
// no regular file (`/dev/null`, a FIFO) is written into directly: renaming over it would
// replace it by a file.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace smachac::driver {

/// Returns an error message, or nullopt on success. "-" writes to stdout.
std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& content);

/// Writes several files (path, content) together: every content goes to its temporary file
/// first, and the files are renamed into place only when all were written. Returns an error
/// message, or nullopt on success.
std::optional<std::string> writeFilesAtomically(
    const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace smachac::driver
