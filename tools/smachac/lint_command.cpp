// `smachac lint script.yml...`: every check on every script, nothing written.
#include "tools/smachac/args.h"
#include "tools/smachac/commands.h"
#include "tools/smachac/script_inputs.h"
#include "tools/smachac/session.h"
#include "tools/smachac/warning_help.h"

namespace smachac::driver {

int runLint(const Args& raw_args) {
  Args args = raw_args;
  std::vector<std::string> warning_flags = takeWarningFlags(args);
  CLI::App app{"smachac lint: check scripts (parse and every pass) and write nothing",
               "smachac lint"};
  ScriptInputs scripts;
  CommonOptions common;
  addScriptInputs(app, scripts);
  app.add_option("--target", common.target, "target whose naming rules apply");
  addCommonOptions(app, common);
  if (std::optional<int> code = parseArgs(app, args)) return *code;
  if (common.list_passes) return printPassList(), kExitOk;
  if (scripts.list_warnings) return printWarningList(), kExitOk;
  if (scripts.inputs.empty()) {
    return usageError("lint: no input script (see `smachac lint --help`)");
  }
  common.sub_script_alone = true;
  Session session;
  if (std::optional<std::string> error = session.configure(warning_flags, common)) {
    return usageError(*error);
  }
  return checkScripts(session, scripts.inputs);
}

}  // namespace smachac::driver
