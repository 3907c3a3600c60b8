// The keys a script root may have, and the checks on them: unknown keys are warned about
// (with a suggestion), required keys (name, template, states) must be present.
#pragma once

#include "ir/state.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/value.h"

namespace smachac::frontend {

/// Checks the root mapping's keys and fills the root state's name, template, outcomes,
/// userdata and arguments. Returns false when a required key is missing.
bool buildRootState(const ir::Value& root, ir::State& state, DiagnosticEmitter& diags);

}  // namespace smachac::frontend
