// Linting a sub-script on its own (`smachac lint sub/pick.yml`): its one state runs in a
// stand-in script that gives what only a caller would:
//   * the state's outcomes are the script's outcomes (a caller maps them);
//   * the keys the state reads (`input_keys`, through its remapping) are defined in the
//     script's userdata as null, which has any type;
//   * the keys it writes (`output_keys`, through its remapping) are the script's output keys,
//     so that they count as read;
//   * the params its lookups read (`[params, x]`, `[[x]]`) are the script's params, as null:
//     a caller gives them (the state's own params still win, as they would);
//   * its own `transitions`, which name the caller's states, are left out.
// The stand-in script is named after the state, with template `Base`. Everything else (the
// states inside, their templates, userdata flow, lookups of the state's own params) is
// checked as in a script.
#pragma once

#include <vector>

#include "ir/state.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/value.h"

namespace smachac::frontend {

struct StandaloneScript {
  ir::Value root;                     ///< the stand-in script, to lower as any script
  std::vector<ir::Name> output_keys;  ///< the output keys of its root state
};

/// True when `root` has a sub-script's shape: a list holding one single-key mapping whose
/// value is a mapping.
bool isSubScript(const ir::Value& root);

/// The stand-in script for the sub-script `root` (isSubScript(root)); expands the state's
/// shorthand keys.
StandaloneScript standaloneScript(const ir::Value& root, DiagnosticEmitter& diags);

}  // namespace smachac::frontend
