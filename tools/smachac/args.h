// Command-line spelling: smachac accepts LLVM-style single-dash long options (-target=smach,
// -fsyntax-only, -list-passes) as well as GNU double-dash ones, and clang-style -W flags.
#pragma once

#include <string>
#include <vector>

namespace smachac::driver {

/// Rewrites single-dash long options that CLI11 would read as short-option clusters
/// (`-target=x` → `--target=x`). Short options (-I, -S, -o, -i, -c) and -W flags are kept.
std::vector<std::string> normalizeArgs(std::vector<std::string> args);

/// Removes -W<...> flags from `args` and returns them in order.
std::vector<std::string> takeWarningFlags(std::vector<std::string>& args);

}  // namespace smachac::driver
