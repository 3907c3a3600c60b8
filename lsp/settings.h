// The server's settings, as the command line gives them (`smachac lsp --target=cpp -I dir
// -S dir -W...`) and as the editor does, in `initializationOptions` or in the `smachac`
// section of `workspace/configuration`:
//   {"target": "smach", "templateDirs": [...], "scriptDirs": [...], "warnings": ["-Werror"]}
// Relative directories are taken from the server's working directory.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "checker/check_script.h"
#include "ir/support/warning_options.h"
#include "lsp/json_rpc.h"

namespace smachac::lsp {

struct Settings {
  std::string target = "smach";
  std::vector<std::string> template_dirs;
  std::vector<std::string> script_dirs;
  std::vector<std::string> warning_flags;  ///< as on the command line: `-Werror`, `-Wno-x`

  friend bool operator==(const Settings&, const Settings&) = default;
};

/// The settings `json` gives over `base` (absent keys keep their value); an error message
/// when a value has the wrong type, the target is unknown or a -W flag is not one.
std::optional<std::string> applySettings(Settings& settings, const Json& json);

/// Checks the -W flags and the target; an error message or nullopt.
std::optional<std::string> validateSettings(const Settings& settings);

WarningOptions warningOptions(const Settings& settings);
checker::CheckOptions checkOptions(const Settings& settings);

}  // namespace smachac::lsp
