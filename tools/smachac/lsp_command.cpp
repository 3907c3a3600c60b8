// `smachac lsp [--target=T] [-I dir]... [-S dir]... [-W...]`: the language server on standard
// input and output. The options are the starting settings; the editor's
// initializationOptions and workspace configuration override them.
#include <iostream>

#include "lsp/server.h"
#include "tools/smachac/args.h"
#include "tools/smachac/commands.h"
#include "tools/smachac/session.h"
#include "tools/smachac/warning_help.h"

namespace smachac::driver {

int runLsp(const Args& raw_args) {
  Args args = raw_args;
  lsp::Settings settings;
  settings.warning_flags = takeWarningFlags(args);
  CLI::App app{"smachac lsp: a Language Server Protocol 3.17 server on standard input/output",
               "smachac lsp"};
  app.add_option("--target", settings.target, "target whose checks apply (smach, flexbe, cpp)");
  addSearchDirectories(app, settings.template_dirs, settings.script_dirs);
  bool list_warnings = false;
  app.add_flag("--list-warnings", list_warnings,
               "list the diagnostic kinds, their defaults and groups, and exit");
  app.footer(warningFlagsHelp());
  if (std::optional<int> code = parseArgs(app, args)) return *code;
  if (list_warnings) return printWarningList(), kExitOk;
  if (std::optional<std::string> error = lsp::validateSettings(settings)) {
    return usageError(*error);
  }
  std::ios::sync_with_stdio(false);
  lsp::Server server(std::cin, std::cout, std::move(settings));
  return server.run();
}

}  // namespace smachac::driver
