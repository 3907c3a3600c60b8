// Resolves every transition target of a module: a child of the same container (Sibling), else
// an outcome of the enclosing container (ContainerOutcome), else Unresolved — which the
// transition checks report. A sibling wins over a container outcome of the same name.
#pragma once

#include "ir/module.h"

namespace smachac::frontend {

void resolveTransitions(ir::Module& module);

}  // namespace smachac::frontend
