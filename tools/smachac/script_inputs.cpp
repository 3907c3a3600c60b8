// Script arguments and checking scripts, shared by compile and lint.
#include "tools/smachac/script_inputs.h"

#include "tools/smachac/args.h"
#include "tools/smachac/warning_help.h"

namespace smachac::driver {

void addScriptInputs(CLI::App& app, ScriptInputs& scripts) {
  app.add_option("inputs", scripts.inputs, "script files (`-`: standard input)")
      ->type_name("SCRIPT");
  app.add_flag("--list-warnings", scripts.list_warnings,
               "list the diagnostic kinds, their defaults and groups, and exit");
  app.footer(warningFlagsHelp());
}

int checkScripts(Session& session, const std::vector<std::string>& inputs) {
  bool ok = true;
  for (const std::string& input : inputs) ok = session.compile(input).has_value() && ok;
  session.printDiagnostics();
  return ok && !session.diags().hasErrors() ? kExitOk : session.failureExitCode();
}

}  // namespace smachac::driver
