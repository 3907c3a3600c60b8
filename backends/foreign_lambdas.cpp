// checkLambdaLanguage (foreign_lambdas.h).
#include "backends/foreign_lambdas.h"

#include <string>
#include <string_view>

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

class LambdaChecker {
 public:
  LambdaChecker(DiagnosticEmitter& diags, const std::string& state, CodeLanguage target)
      : diags_(diags), state_(state), target_(target) {}

  void check(const ir::Value& value, const std::string& what) {
    if (value.kind() == ir::ValueKind::Expression) {
      if (isForeign(value.asExpression().code)) report(value.loc, what);
    } else if (value.isList()) {
      for (const ir::Value& item : std::get<ir::List>(value.data)) check(item, what);
    } else if (value.isMap()) {
      for (const ir::MapEntry& entry : std::get<ir::Map>(value.data)) check(entry.value, what);
    }
  }

  bool clean() const { return clean_; }

 private:
  bool isForeign(std::string_view code) const {
    return target_ == CodeLanguage::Cpp ? isPythonLambda(code) : isCppLambda(code);
  }

  void report(SourceLoc loc, const std::string& what) {
    DiagKind kind =
        target_ == CodeLanguage::Cpp ? DiagKind::PythonCodeInCpp : DiagKind::CppCodeInPython;
    diags_.emit(kind, loc, what, state_);
    clean_ = false;
  }

  DiagnosticEmitter& diags_;
  const std::string& state_;
  CodeLanguage target_;
  bool clean_ = true;
};

}  // namespace

bool checkLambdaLanguage(const ir::Module& module, DiagnosticEmitter& diags, CodeLanguage target) {
  bool clean = true;
  for (ir::StateId id : module.preorder()) {
    const ir::State& state = module.state(id);
    LambdaChecker checker(diags, state.name.text, target);
    for (const ir::Argument& callback : state.callbacks) {
      checker.check(callback.value, "callback `" + callback.key.text + "`");
    }
    for (const ir::Argument& entry : state.userdata) {
      checker.check(entry.value, "userdata `" + entry.key.text + "`");
    }
    clean = clean && checker.clean();
  }
  return clean;
}

}  // namespace smachac::backends
