// checkPythonCode (python_code_check.h).
#include "backends/python_code_check.h"

#include <string>

#include "backends/code_values.h"
#include "backends/smach/python_expression.h"

namespace smachac::backends {
namespace {

constexpr size_t kShownCode = 60;  // bytes of the code quoted in the message

std::string shown(const std::string& code) {
  std::string text = code.size() <= kShownCode ? code : code.substr(0, kShownCode) + "...";
  for (char& c : text) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  }
  return text;
}

}  // namespace

bool checkPythonCode(const ir::Module& module, DiagnosticEmitter& diags) {
  const size_t errors_before = diags.errorCount();
  forEachCode(module, [&](const CodeSite& site) {
    const std::string& code = site.value.asExpression().code;
    if (auto error = pythonExpressionError(code)) {
      diags.emit<DiagKind::PythonSyntax>(site.value.loc, site.what, site.state, error->message,
                                         error->offset + 1, shown(code));
    }
  });
  return diags.errorCount() == errors_before;
}

}  // namespace smachac::backends
