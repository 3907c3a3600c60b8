// Lowering of portable callbacks to target code.
#include "backends/expr/lower_expressions.h"

#include "backends/expr/cpp_lambda.h"
#include "backends/expr/python_lambda.h"

namespace smachac::backends::expr {

void lowerPortableExpressions(ir::Module& module, std::string_view target) {
  bool python = target == "smach" || target == "flexbe";
  if (!python && target != "cpp") return;
  for (ir::StateId id : module.preorder()) {
    ir::State& state = module.state(id);
    for (ir::Argument& callback : state.callbacks) {
      const ir::PortableExpr* expr = callback.value.asPortable();
      if (!expr) continue;
      std::string code = python ? pythonLambda(*expr, state) : cppLambda(*expr, state);
      callback.value = ir::Value::expression(std::move(code), callback.value.loc);
    }
  }
}

}  // namespace smachac::backends::expr
