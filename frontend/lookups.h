// SMACHA's params inheritance and lookups, applied to a state's keys before it is typed
// (SMACHA's lookup rules):
//   * params: a state without `params` gets the inherited ones; a state with its own gets
//     the inherited keys it lacks (its own values win).
//   * lookups, in key order, each seeing the keys as rewritten so far: a key whose value is
//     `[k]` becomes the state's key k, `[k, j]` becomes entry j of key k (any key, not only
//     params); `[[x]]` means `[params, x]`. A list with at least one lookup among strings and
//     scalars is a string construct: the parts are joined as Python str() would.
//     Mappings get the same treatment for their immediate list values.
// A failed `[params, x]` is an error (SMACHA silently kept the list); other lists that are no
// lookup stay lists.
#pragma once

#include <optional>

#include "ir/support/diagnostic_emitter.h"
#include "ir/value.h"

namespace smachac::frontend {

void inheritParams(ir::Value& state_vars, const std::optional<ir::Value>& inherited);

void resolveLookups(ir::Value& state_vars, DiagnosticEmitter& diags);

}  // namespace smachac::frontend
