// check-expressions: portable expressions (`!expr`, ir/expr.h).
//   * every callback written as `!expr` is type-checked against the userdata of its state
//     (passes/analysis/expr_typer.h lists the rules and the diagnostics)
//   * expr-outside-callback  an `!expr` in userdata or in a template variable: it is a
//                            function of the userdata, which only a callback is given. (A
//                            param may hold one: it is checked where a lookup puts it.)
#include <string>

#include "ir/expr.h"
#include "passes/analysis/expr_typer.h"
#include "passes/validate/checks.h"

namespace smachac::passes {
namespace {

void reportOutside(const ir::Value& value, const std::string& what, const ir::State& state,
                   DiagnosticEmitter& diags) {
  if (value.asPortable()) {
    diags.emit<DiagKind::ExprOutsideCallback>(value.loc, what, state.name.text);
  } else if (value.isList()) {
    for (const ir::Value& item : value.asList()) reportOutside(item, what, state, diags);
  } else if (value.isMap()) {
    for (const ir::MapEntry& entry : value.asMap()) {
      reportOutside(entry.value, what, state, diags);
    }
  }
}

void checkState(const ir::State& state, ExprTyper& typer, DiagnosticEmitter& diags) {
  for (const ir::Argument& callback : state.callbacks) {
    if (const ir::PortableExpr* expr = callback.value.asPortable()) {
      typer.check(*expr, state);
    } else {
      reportOutside(callback.value, "a value inside callback `" + callback.key.text + "`", state,
                    diags);
    }
  }
  for (const ir::Argument& entry : state.userdata) {
    reportOutside(entry.value, "userdata `" + entry.key.text + "`", state, diags);
  }
  for (const ir::Argument& argument : state.args) {
    reportOutside(argument.value, "template variable `" + argument.key.text + "`", state, diags);
  }
}

}  // namespace

void checkExpressions(const ir::Module& module, PassContext& context) {
  KeyTypes key_types(module);
  ExprTyper typer(key_types, context.diags);
  for (ir::StateId id : module.preorder()) checkState(module.state(id), typer, context.diags);
}

}  // namespace smachac::passes
