// checkTargetCode (target_code_check.h).
#include "backends/target_code_check.h"

#include "backends/foreign_lambdas.h"
#include "backends/python_code_check.h"

namespace smachac::backends {

bool checkTargetCode(const ir::Module& module, std::string_view target, DiagnosticEmitter& diags) {
  if (target == "cpp") return checkLambdaLanguage(module, diags, CodeLanguage::Cpp);
  if (target != "smach" && target != "flexbe") return true;
  // A C++ lambda is reported as one, not also as broken Python.
  return checkLambdaLanguage(module, diags, CodeLanguage::Python) && checkPythonCode(module, diags);
}

}  // namespace smachac::backends
