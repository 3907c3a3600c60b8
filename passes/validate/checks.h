// The checks: read-only passes that report every problem they find. One check per file; the
// header comment of each file lists the rules it enforces. Ordered in passes/pipeline.cpp.
#pragma once

#include "passes/pass.h"

namespace smachac::passes {

void checkNames(const ir::Module& module, PassContext& context);
void checkTransitions(const ir::Module& module, PassContext& context);
void checkConcurrence(const ir::Module& module, PassContext& context);
void checkReachability(const ir::Module& module, PassContext& context);
void checkUserdataFlow(const ir::Module& module, PassContext& context);
void checkUserdataUsage(const ir::Module& module, PassContext& context);
void checkUserdataTypes(const ir::Module& module, PassContext& context);
void checkExpressions(const ir::Module& module, PassContext& context);

}  // namespace smachac::passes
