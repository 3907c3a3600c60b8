// Portable expressions in C++.
#include "backends/expr/cpp_lambda.h"

#include "backends/cpp/cpp_extensions.h"
#include "backends/generator/template_values.h"
#include "ir/expr_names.h"

namespace smachac::backends::expr {
namespace {

using ir::ExprOp;

std::string valueOf(const ir::Value& value) {
  if (value.kind() == ir::ValueKind::Expression) {
    return "rt::Value(" + value.asExpression().code + ")";
  }
  generator::ValueConverter converter;
  return "rt::Value(" + cpp::cppValueExpression(converter.convert(value)) + ")";
}

/// The rt::ops function of an operator that maps to one.
std::string_view opsFunction(ExprOp op) {
  switch (op) {
    case ExprOp::Negate:
      return "negate";
    case ExprOp::Plus:
      return "plus";
    case ExprOp::Add:
      return "add";
    case ExprOp::Subtract:
      return "subtract";
    case ExprOp::Multiply:
      return "multiply";
    case ExprOp::Divide:
      return "divide";
    case ExprOp::FloorDivide:
      return "floorDivide";
    case ExprOp::Modulo:
      return "modulo";
    case ExprOp::Equal:
      return "equal";
    case ExprOp::NotEqual:
      return "notEqual";
    case ExprOp::Less:
      return "less";
    case ExprOp::LessEqual:
      return "lessEqual";
    case ExprOp::Greater:
      return "greater";
    case ExprOp::GreaterEqual:
      return "greaterEqual";
    default:
      return "";
  }
}

class CppWriter {
 public:
  explicit CppWriter(const ir::State& state) : state_(state) {}

  std::string write(const ir::ExprNode& node) {
    switch (node.op) {
      case ExprOp::Literal:
        return valueOf(node.literal);
      case ExprOp::Name:
        return name(node);
      case ExprOp::Not:
        return "rt::Value(!(" + write(node.operands[0]) + ").truthy())";
      case ExprOp::And:
      case ExprOp::Or:
        return logical(node);
      case ExprOp::Conditional:
        return "((" + write(node.operands[0]) + ").truthy() ? " + write(node.operands[1]) + " : " +
               write(node.operands[2]) + ")";
      case ExprOp::Call:
        return call(node);
      default:
        break;
    }
    std::string call =
        "rt::ops::" + std::string(opsFunction(node.op)) + "(" + arguments(node) + ")";
    return ir::isComparisonOp(node.op) ? "rt::Value(" + call + ")" : call;
  }

 private:
  std::string name(const ir::ExprNode& node) {
    ir::ExprName bound = ir::bindExprName(state_, node.name);
    if (bound.kind == ir::ExprNameKind::Param) return valueOf(*bound.param);
    std::string key = cpp::cppStringLiteral(node.name);
    if (bound.kind != ir::ExprNameKind::InputKey) return "ud.at(" + key + ")";
    // The key's position among the state's input keys: the runtime reads it without a search.
    return "ud.at(" + key + ", " + std::to_string(bound.key - state_.input_keys.data()) + ")";
  }

  std::string logical(const ir::ExprNode& node) {
    std::string function = node.op == ExprOp::And ? "logicalAnd" : "logicalOr";
    return "rt::ops::" + function + "(" + write(node.operands[0]) + ", [&] { return " +
           write(node.operands[1]) + "; })";
  }

  std::string call(const ir::ExprNode& node) {
    bool variadic = node.name == "min" || node.name == "max";
    std::string args = arguments(node);
    return "rt::ops::" + node.name + (variadic ? "({" + args + "})" : "(" + args + ")");
  }

  std::string arguments(const ir::ExprNode& node) {
    std::string out;
    for (const ir::ExprNode& operand : node.operands) {
      if (!out.empty()) out += ", ";
      out += write(operand);
    }
    return out;
  }

  const ir::State& state_;
};

}  // namespace

std::string cppLambda(const ir::PortableExpr& expr, const ir::State& state) {
  return "[](rt::UserData& ud) -> rt::Value { return " + CppWriter(state).write(expr.root) + "; }";
}

}  // namespace smachac::backends::expr
