// Writing generated files atomically: the content goes to a temporary file next to the
// destination, which is then renamed over it. A failed run never leaves a partial file and
// never clobbers an existing one.
#pragma once

#include <optional>
#include <string>

namespace smachac::driver {

/// Returns an error message, or nullopt on success. "-" writes to stdout.
std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& content);

}  // namespace smachac::driver
