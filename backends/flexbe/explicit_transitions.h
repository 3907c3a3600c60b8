// FlexBE wants every outcome of every state connected (the editor refuses a behavior with an
// unconnected outcome, and the engine cannot return one), where SMACH lets an outcome without
// a transition leave its container by the container outcome of the same name, and ignores the
// transitions of a Concurrence's children. SMACHA scripts rely on both. The FlexBE target
// makes those transitions explicit. A state's outcomes are its script's `outcomes` and, for a
// leaf, the `outcomes` of its template's meta block.
//   * A child of a Concurrence without transitions gets them from the container's
//     outcome_map: each condition {child: child_outcome} of an entry connects child_outcome to
//     the entry's outcome (the first entry in script order wins); its other outcomes go to the
//     default outcome.
//   * Any outcome still without a transition goes to the container outcome of the same name,
//     when there is one (else the checks have already reported it, or it stays unconnected).
//   * FlexBE's ConcurrencyContainer has no default outcome: when its children have finished
//     and no condition holds, it waits. A Concurrence with a `default_outcome` gets the
//     template argument `default_conditions`: every combination of its children's outcomes
//     that no outcome_map entry with conditions matches ([[child, outcome], ...] each), which
//     its template adds after the outcome_map's conditions, leading to the default outcome.
//     Beyond 64 combinations the default outcome is left out, with warning
//     flexbe-default-outcome-lost.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"

namespace smachac::backends::flexbe {

/// The outcomes a template's meta block declares, by template name (empty when unknown).
using TemplateOutcomes = std::function<std::vector<std::string>(const std::string&)>;

/// A copy of `module` with the transitions and default conditions above made explicit.
ir::Module withExplicitTransitions(const ir::Module& module,
                                   const TemplateOutcomes& template_outcomes,
                                   DiagnosticEmitter& diags);

}  // namespace smachac::backends::flexbe
