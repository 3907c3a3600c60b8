// FlexBE's editor wants every outcome of a ConcurrencyContainer's child connected to one of
// the container's outcomes; SMACH ignores such transitions, so SMACHA scripts usually leave
// them out. For a child of a Concurrence that has no transitions, they are derived from the
// container's outcome_map: each condition {child: child_outcome} of an entry connects
// child_outcome to the entry's outcome (the first entry in script order wins), and the child's
// other declared outcomes go to the default outcome.
#pragma once

#include "ir/module.h"

namespace smachac::backends::flexbe {

/// A copy of `module` in which every transition-less Concurrence child has its derived
/// transitions.
ir::Module withConcurrenceTransitions(const ir::Module& module);

}  // namespace smachac::backends::flexbe
