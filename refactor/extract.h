// `smachac extract`: turns a root state into a sub-script and the script into its
// super-script (SMACHA's extract, with its bugs fixed). Rules:
//   * the state must be a root state (selection.h); SMACHA used the last one otherwise
//   * its `params`, `userdata`, `remapping` and `transitions` (long or short spelling) stay
//     in the super-script, in their order, after a new `script: <sub-script name>` (`S:`
//     when the state is written in shorthand), which is what SMACHA's sub-script includes
//     pass on (as SMACHA's params do)
//   * every other key moves to the sub-script: a one-state list `- STATE: {...}`, the state's
//     text de-indented so that its dash is at column 0
//   * in block style each key takes its lines and the comment lines above it along; a flow
//     body is rewritten as a flow mapping of the keys' texts
//   * the rest of the script keeps its text; the input is never modified
#pragma once

#include <optional>
#include <string>

#include "ir/support/diagnostic_emitter.h"
#include "refactor/script_view.h"

namespace smachac::refactor {

struct ExtractResult {
  std::string sub_script;
  std::string super_script;
};

/// Extracts root state `state`; `sub_name` is how the super-script names the sub-script.
std::optional<ExtractResult> extract(const ScriptView& script, const std::string& state,
                                     const std::string& sub_name, DiagnosticEmitter& diags);

}  // namespace smachac::refactor
