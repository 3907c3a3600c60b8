// Types a state's resolved keys into an ir::State. Core keys:
//   template: name            outcomes, input_keys, output_keys: [name, ...]
//   transitions: {outcome: target}      remapping: {state_key: parent_key}
//   userdata: {key: value}    callbacks: {output_key: name | `lambda`}     params: {...}
//   outcome_map: {outcome: {child: child_outcome}}                default_outcome: name
// `states` and `script` are structure, handled by the lowering. Every other key becomes a
// template argument. A core key of the wrong shape is an invalid-key-type error.
#pragma once

#include <string_view>

#include "ir/state.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/value.h"

namespace smachac::frontend {

/// Fills `state`'s typed fields from `vars` (a mapping). `what` names the state in messages,
/// e.g. "state `FOO`".
void buildStateFields(const ir::Value& vars, ir::State& state, std::string_view what,
                      DiagnosticEmitter& diags);

/// Reads a scalar name (string, or an int/bool written bare, kept as its text). Emits
/// invalid-key-type and returns false otherwise.
bool readName(const ir::Value& value, std::string_view what, ir::Name& out,
              DiagnosticEmitter& diags);

}  // namespace smachac::frontend
