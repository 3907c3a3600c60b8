// Entry points of the driver's subcommands. Each takes the arguments after the subcommand
// word (already normalised by normalizeArgs) and returns the process exit code:
// 0 success, 1 the input has errors, 2 usage or I/O error.
#pragma once

#include <string>
#include <vector>

namespace smachac::driver {

using Args = std::vector<std::string>;

enum ExitCode : int { kExitOk = 0, kExitInputError = 1, kExitUsageError = 2 };

int runCompile(const Args& args);
#define SMACHAC_COMMAND(word, function, help) int function(const Args& args);
#include "tools/smachac/commands.def"

}  // namespace smachac::driver
