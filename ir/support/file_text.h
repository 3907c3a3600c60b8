// A whole file's bytes, read once for everybody who needs a file as text (templates, scripts,
// a render's context, a FlexBE behavior's existing manual sections). Not for scripts given to
// the compiler: the frontend reads those with its own size limit and located diagnostics.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace smachac {

/// The bytes of the regular file at `path`, or nullopt when there is none (a missing file, a
/// directory) or it cannot be read.
std::optional<std::string> readFileText(const std::string& path);

/// The bytes left in the open file `fd`, read to its end (`expected_size` is a first guess: a
/// file may change while it is read); nullopt on a read error.
std::optional<std::string> readOpenFile(int fd, size_t expected_size);

}  // namespace smachac
