// The checks of backtick code for the target it is compiled for, run on every compile and by
// `smachac lint`: a lambda of the other language (foreign_lambdas.h), and under a Python target
// code that is not a Python expression (python_code_check.h).
#pragma once

#include <string_view>

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"

namespace smachac::backends {

/// Reports the backtick code of `module` that cannot work under `target` (smach, flexbe or
/// cpp; other targets write no code); returns whether there was no error.
bool checkTargetCode(const ir::Module& module, std::string_view target, DiagnosticEmitter& diags);

}  // namespace smachac::backends
