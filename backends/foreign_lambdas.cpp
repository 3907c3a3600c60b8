// checkLambdaLanguage (foreign_lambdas.h).
#include "backends/foreign_lambdas.h"

#include <string>
#include <string_view>

#include "backends/code_values.h"

namespace smachac::backends {
namespace {

std::string_view trimmedStart(std::string_view code, std::string_view skipped) {
  size_t start = code.find_first_not_of(skipped);
  return start == std::string_view::npos ? std::string_view() : code.substr(start);
}

/// `lambda x: ...`, `(lambda: ...)`.
bool isPythonLambda(std::string_view code) {
  code = trimmedStart(code, " \t\r\n(");
  if (!code.starts_with("lambda")) return false;
  return code.size() > 6 && (code[6] == ' ' || code[6] == ':' || code[6] == '\t');
}

/// `[](rt::UserData& ud) { ... }`, `[&] { ... }`: a capture list followed by parameters or a
/// body (a Python list is followed by neither).
bool isCppLambda(std::string_view code) {
  code = trimmedStart(code, " \t\r\n");
  if (!code.starts_with("[")) return false;
  size_t close = code.find(']');
  if (close == std::string_view::npos) return false;
  std::string_view rest = trimmedStart(code.substr(close + 1), " \t\r\n");
  return rest.starts_with("(") || rest.starts_with("{");
}

}  // namespace

bool checkLambdaLanguage(const ir::Module& module, DiagnosticEmitter& diags, CodeLanguage target) {
  bool clean = true;
  forEachCode(module, [&](const CodeSite& site) {
    const std::string& code = site.value.asExpression().code;
    if (target == CodeLanguage::Cpp ? isPythonLambda(code) : isCppLambda(code)) {
      if (target == CodeLanguage::Cpp) {
        diags.emit<DiagKind::PythonCodeInCpp>(site.value.loc, site.what, site.state);
      } else {
        diags.emit<DiagKind::CppCodeInPython>(site.value.loc, site.what, site.state);
      }
      clean = false;
    }
  });
  return clean;
}

}  // namespace smachac::backends
