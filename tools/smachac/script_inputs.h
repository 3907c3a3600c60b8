// What the commands that take scripts share (compile and lint): the script arguments with the
// -W help and --list-warnings, and checking scripts without writing anything.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "tools/smachac/session.h"

namespace smachac::driver {

struct ScriptInputs {
  std::vector<std::string> inputs;
  bool list_warnings = false;
};

/// The positional scripts, --list-warnings and the -W help footer.
void addScriptInputs(CLI::App& app, ScriptInputs& scripts);

/// Compiles every script through every check and prints the diagnostics; the exit code.
int checkScripts(Session& session, const std::vector<std::string>& inputs);

}  // namespace smachac::driver
