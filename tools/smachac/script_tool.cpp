// The script tools' shared command-line handling.
#include "tools/smachac/script_tool.h"

#include <iostream>

#include "tools/smachac/args.h"

namespace smachac::driver {

ScriptTool::ScriptTool(std::string command, const std::string& description)
    : command_(std::move(command)), app_(description, "smachac " + command_) {
  app_.add_option("-S,--script-dir", common_.script_dirs,
                  "sub-script search directory, after the script's own (repeatable)")
      ->allow_extra_args(false);
  app_.add_option("--fdiagnostics-format", common_.diagnostics_format,
                  "diagnostics as text, json or sarif")
      ->check(CLI::IsMember({"text", "json", "sarif"}));
}

std::optional<int> ScriptTool::start(const Args& raw_args,
                                     const std::function<std::optional<std::string>()>& check) {
  Args args = raw_args;
  std::vector<std::string> warning_flags = takeWarningFlags(args);
  if (std::optional<int> code = parseArgs(app_, args)) return code;
  if (std::optional<std::string> error = check()) return usageError(*error);
  if (std::optional<std::string> error = session_.configure(warning_flags, common_)) {
    return usageError(*error);
  }
  return std::nullopt;
}

std::optional<refactor::ScriptView> ScriptTool::load(const std::string& path) {
  return refactor::ScriptView::load(path, {common_.script_dirs}, session_.sources(),
                                    session_.diags());
}

std::optional<int> ScriptTool::report(bool ok) {
  session_.printDiagnostics();
  if (!ok || session_.diags().hasErrors()) return session_.failureExitCode();
  return std::nullopt;
}

int ScriptTool::usageError(const std::string& message) const {
  std::cerr << "smachac " << command_ << ": error: " << message << "\n";
  return kExitUsageError;
}

}  // namespace smachac::driver
