// The transforms: passes that rewrite the IR without changing what the generated machine
// does, and return whether they changed anything. They run only when optimisation is asked
// for (PipelineOptions::optimize) and the module has no errors. One transform per file; the
// header comment of each file shows its input and output. Ordered in passes/pipeline.cpp.
#pragma once

#include "passes/pass.h"

namespace smachac::passes {

bool pruneUnreachableStates(ir::Module& module, PassContext& context);
bool dedupeUserdata(ir::Module& module, PassContext& context);
bool foldTrivialContainers(ir::Module& module, PassContext& context);

}  // namespace smachac::passes
