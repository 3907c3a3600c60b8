// What the script tools (contain, extract) share in the driver: the command line (positional
// arguments set up by the command, plus -S, -W and -fdiagnostics-format), the session, and
// loading the script for editing. Usage errors exit 2, errors in the script 1.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "refactor/script_view.h"
#include "tools/smachac/session.h"

namespace smachac::driver {

class ScriptTool {
 public:
  ScriptTool(std::string command, const std::string& description);

  CLI::App& app() { return app_; }
  Session& session() { return session_; }
  const std::vector<std::string>& scriptDirs() const { return common_.script_dirs; }

  /// Parses the command line, runs `check` on it (a usage problem, or nullopt) and sets up
  /// the session; an exit code when the command must stop.
  std::optional<int> start(const Args& raw_args,
                           const std::function<std::optional<std::string>()>& check);

  /// Loads the script (diagnostics are kept for print()).
  std::optional<refactor::ScriptView> load(const std::string& path);

  /// Prints the diagnostics; kExitInputError when there are errors or `ok` is false.
  std::optional<int> report(bool ok);

  int usageError(const std::string& message) const;

 private:
  std::string command_;
  CLI::App app_;
  CommonOptions common_;
  Session session_;
};

}  // namespace smachac::driver
