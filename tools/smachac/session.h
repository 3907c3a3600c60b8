// What every command shares: the options common to compile and lint (-I, -S, -W,
// -fdiagnostics-format, pass flags), the source manager and the diagnostic emitter, and the
// compile of one script up to a checked module.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/diagnostic_printer.h"
#include "ir/support/source_manager.h"
#include "tools/smachac/commands.h"

namespace smachac::driver {

/// The input path that stands for standard input, and its name in diagnostics. Sub-scripts
/// of a script read from standard input are searched in the working directory, then -S.
inline constexpr std::string_view kStandardInputPath = "-";
inline constexpr std::string_view kStandardInputName = "<stdin>";

struct CommonOptions {
  std::vector<std::string> template_dirs;
  std::vector<std::string> script_dirs;
  std::string diagnostics_format = "text";
  std::string target = "smach";
  std::vector<std::string> disabled_passes;
  std::string print_ir_after;
  bool list_passes = false;
  bool optimize = false;
  bool sub_script_alone = false;  ///< lint: check a sub-script on its own
};

/// Registers -I and -S (template and sub-script search directories) on a CLI11 app.
void addSearchDirectories(CLI::App& app, std::vector<std::string>& template_dirs,
                          std::vector<std::string>& script_dirs);

/// Registers the common options on a CLI11 app (-I and -S among them).
void addCommonOptions(CLI::App& app, CommonOptions& options);

class Session {
 public:
  /// Applies -W flags; returns an error message for an unknown one.
  std::optional<std::string> configure(const std::vector<std::string>& warning_flags,
                                       const CommonOptions& options);

  /// Frontend + passes for one script (`-`: standard input); nullopt when it has errors.
  std::optional<ir::Module> compile(const std::string& path);

  /// Prints the diagnostics collected so far to stderr.
  void printDiagnostics() const;

  /// The exit code of a run that failed: 2 when a file could not be read, else 1.
  int failureExitCode() const;

  SourceManager& sources() { return sources_; }
  DiagnosticEmitter& diags() { return *diags_; }
  const CommonOptions& options() const { return options_; }

 private:
  CommonOptions options_;
  DiagnosticFormat format_ = DiagnosticFormat::Text;
  SourceManager sources_;
  std::unique_ptr<DiagnosticEmitter> diags_ = std::make_unique<DiagnosticEmitter>();
};

/// Parses `args` with `app`; on failure prints CLI11's message and returns the exit code.
std::optional<int> parseArgs(CLI::App& app, const Args& args);

/// Prints the pass table (for -list-passes).
void printPassList();

/// Prints `smachac: error: <message>` and returns the usage error's exit code.
int usageError(const std::string& message);

}  // namespace smachac::driver
