// Backtick code under a Python target (smach, flexbe) must be a Python expression: code that
// does not parse is a located error (python-syntax) instead of a generated program that does
// not compile. An error that can be downgraded (-Wno-error=python-syntax) for code smachac
// reads wrongly.
#pragma once

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"

namespace smachac::backends {

/// Reports every backtick value of `module` (userdata, callbacks, template variables) that is
/// not a Python expression; returns whether there was no error.
bool checkPythonCode(const ir::Module& module, DiagnosticEmitter& diags);

}  // namespace smachac::backends
