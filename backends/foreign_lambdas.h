// Backtick code in the other target language: a Python lambda under -target=cpp, or a C++
// lambda under -target=smach or flexbe, is a located error (python-code-in-cpp,
// cpp-code-in-python) instead of output that does not compile.
#pragma once

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"

namespace smachac::backends {

/// The language a target writes backtick code in.
enum class CodeLanguage { Python, Cpp };

/// Reports every backtick value of `module` (callbacks, userdata, template variables) that is
/// a lambda of the other language; returns whether there was none.
bool checkLambdaLanguage(const ir::Module& module, DiagnosticEmitter& diags, CodeLanguage target);

}  // namespace smachac::backends
