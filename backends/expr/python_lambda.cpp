// Portable expressions in Python.
#include "backends/expr/python_lambda.h"

#include "backends/generator/template_values.h"
#include "backends/smach/python_code.h"
#include "ir/expr_names.h"

namespace smachac::backends::expr {
namespace {

std::string literal(const ir::Value& value) {
  if (value.kind() == ir::ValueKind::Expression) return "(" + value.asExpression().code + ")";
  generator::ValueConverter converter;
  return smach::pythonLiteral(converter.convert(value));
}

}  // namespace

std::string pythonLambda(const ir::PortableExpr& expr, const ir::State& state) {
  return "lambda ud: " + ir::printExpr(expr.root, [&](const ir::ExprNode& leaf) {
           if (leaf.op == ir::ExprOp::Literal) return literal(leaf.literal);
           ir::ExprName bound = ir::bindExprName(state, leaf.name);
           if (bound.kind == ir::ExprNameKind::Param) return literal(*bound.param);
           return "ud." + leaf.name;
         });
}

}  // namespace smachac::backends::expr
