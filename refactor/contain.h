// `smachac contain`: replaces a run of consecutive root states by one new container state
// (SMACHA's contain, with its bugs fixed). The steps and their rules:
//   selection.h         which states (consecutive root states, in order)
//   contain_outcomes.h  outcomes, transitions, outcome_map, default outcome, redirects
//   contain_params.h    params lifted into the container, lookups renamed
//   contain_leaks.h     params that leaked from a contained sub-script include kept
//   contain_userdata.h  userdata lifted to the script's root
//   contain_keys.h      input_keys, output_keys, remapping
// The container's name must not be another root state's or an outcome of the script.
// Output: the script's text with the selected states replaced in place by
//   NAME: {template, params, input_keys, output_keys, remapping, outcomes, default_outcome,
//          outcome_map, transitions, states}
// (empty keys left out, small values in flow style). Shorthand scripts are not expanded: the
// user's spelling is kept, and the container's keys are written in shorthand when the first
// selected state is. The selected states move unchanged but for the edits above,
// re-indented under the container's `states` (indented like the root's), with the comment
// lines right above the first of them; everything else keeps its text, comments and line
// breaks (CRLF too) included. When the root `states` list is a flow list, the container is
// written in flow style in its place.
#pragma once

#include <optional>
#include <string>

#include "refactor/contain_scope.h"

namespace smachac::refactor {

/// The contained script's text; nullopt when there are errors (reported).
std::optional<std::string> contain(const ScriptView& script, const ContainRequest& request,
                                   DiagnosticEmitter& diags);

}  // namespace smachac::refactor
