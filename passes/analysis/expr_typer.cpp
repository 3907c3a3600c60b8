// Type rules of portable expressions.
#include "passes/analysis/expr_typer.h"

#include <fmt/core.h>

#include <vector>

#include "ir/expr_names.h"
#include "ir/support/suggest.h"
#include "passes/analysis/userdata_scope.h"

namespace smachac::passes {
namespace {

using ir::ExprOp;
using Kind = ir::Type::Kind;

/// Null (a key set later), backtick code and unknown keys: checked only when the code runs.
bool isAny(const ir::Type& t) {
  return t.kind() == Kind::Any || t.kind() == Kind::Null || t.kind() == Kind::Expression;
}
bool isNumber(const ir::Type& t) { return t.kind() == Kind::Int || t.kind() == Kind::Float; }
bool isOrderable(const ir::Type& t) { return isNumber(t) || t.kind() == Kind::String; }

/// The common type of both sides, `any` when either is.
ir::Type joined(const ir::Type& a, const ir::Type& b) {
  if (isAny(a) || isAny(b)) return ir::Type::any();
  return ir::Type::join(a, b);
}

/// "int", "int and string", "int, string and bool".
std::string typeList(std::span<const ir::Type> types) {
  std::string out;
  for (size_t i = 0; i < types.size(); ++i) {
    if (i > 0) out += i + 1 == types.size() ? " and " : ", ";
    out += types[i].str();
  }
  return out;
}

bool isLiteralZero(const ir::ExprNode& node) {
  if (node.op == ExprOp::Negate || node.op == ExprOp::Plus) return isLiteralZero(node.operands[0]);
  if (node.op != ExprOp::Literal) return false;
  const ir::Value& v = node.literal;
  return (v.kind() == ir::ValueKind::Int && v.asInt() == 0) ||
         (v.kind() == ir::ValueKind::Float && v.asFloat() == 0.0);
}

std::string argumentCount(uint32_t n) { return fmt::format("{} argument{}", n, n == 1 ? "" : "s"); }

}  // namespace

ir::Type ExprTyper::check(const ir::PortableExpr& expr, const ir::State& state) {
  state_ = &state;
  return type(expr.root);
}

ir::Type ExprTyper::type(const ir::ExprNode& node) {
  switch (node.op) {
    case ExprOp::Literal:
      return ir::Type::ofValue(node.literal);
    case ExprOp::Name:
      return name(node);
    case ExprOp::Call:
      return call(node);
    case ExprOp::Conditional: {
      type(node.operands[0]);
      ir::Type then = type(node.operands[1]);
      return joined(then, type(node.operands[2]));
    }
    default:
      break;
  }
  if (ir::isUnaryOp(node.op)) return unary(node, type(node.operands[0]));
  ir::Type left = type(node.operands[0]);
  return binary(node, left, type(node.operands[1]));
}

ir::Type ExprTyper::name(const ir::ExprNode& node) {
  ir::ExprName bound = ir::bindExprName(*state_, node.name);
  switch (bound.kind) {
    case ir::ExprNameKind::Param:
      if (bound.param->asPortable()) {
        // Its names would be bound in this state again (and could name the param itself).
        diags_.emit<DiagKind::ExprOutsideCallback>(bound.param->loc, "param `" + node.name + "`",
                                                   state_->name.text);
        return ir::Type::any();
      }
      return ir::Type::ofValue(*bound.param);
    case ir::ExprNameKind::InputKey: {
      if (!state_->parent.valid()) return ir::Type::any();
      std::optional<ir::Type> t =
          key_types_.find(state_->parent, remappedName(*state_, *bound.key).text);
      return t.value_or(ir::Type::any());
    }
    case ir::ExprNameKind::Unknown:
      return unknownName(node);
  }
  return ir::Type::any();
}

ir::Type ExprTyper::unknownName(const ir::ExprNode& node) {
  bool is_output = false;
  for (const ir::Name& key : state_->output_keys) is_output = is_output || key.text == node.name;
  bool in_scope = state_->parent.valid() && key_types_.find(state_->parent, node.name);
  if (is_output || in_scope) {
    diags_.emit<DiagKind::ExprKeyNotInput>(node.loc, node.name, state_->name.text);
    diags_.note<DiagNoteKind::AddInputKey>(node.loc, node.name, state_->name.text);
    return ir::Type::any();
  }
  std::vector<std::string> candidates;
  for (const ir::Name& key : state_->input_keys) candidates.push_back(key.text);
  if (state_->params && state_->params->isMap()) {
    for (const ir::MapEntry& entry : state_->params->asMap()) candidates.push_back(entry.key);
  }
  std::optional<std::string> match = closestMatch(node.name, candidates);
  diags_.emit<DiagKind::ExprUnknownName>(node.loc, node.name, state_->name.text, didYouMean(match));
  diags_.fixIt(match);
  return ir::Type::any();
}

ir::Type ExprTyper::unary(const ir::ExprNode& node, const ir::Type& operand) {
  if (node.op == ExprOp::Not) return ir::Type::of(Kind::Bool);
  if (isAny(operand)) return ir::Type::any();
  if (isNumber(operand)) return operand;
  return mismatch(node, operand.str());
}

ir::Type ExprTyper::binary(const ir::ExprNode& node, const ir::Type& left, const ir::Type& right) {
  switch (node.op) {
    case ExprOp::And:
    case ExprOp::Or:
      return joined(left, right);
    case ExprOp::Equal:
    case ExprOp::NotEqual:
      return ir::Type::of(Kind::Bool);
    default:
      break;
  }
  if (ir::isComparisonOp(node.op)) {
    bool ok = (isAny(left) && (isAny(right) || isOrderable(right))) ||
              (isAny(right) && isOrderable(left)) || (isNumber(left) && isNumber(right)) ||
              (left.kind() == Kind::String && right.kind() == Kind::String);
    if (!ok) return mismatch(node, typeList(std::vector{left, right}));
    return ir::Type::of(Kind::Bool);
  }
  return arithmetic(node, left, right);
}

ir::Type ExprTyper::arithmetic(const ir::ExprNode& node, const ir::Type& left,
                               const ir::Type& right) {
  if (node.op == ExprOp::Divide || node.op == ExprOp::FloorDivide || node.op == ExprOp::Modulo) {
    checkDivisor(node);
  }
  bool concatenates = node.op == ExprOp::Add;
  auto operand_ok = [&](const ir::Type& t) {
    return isAny(t) || isNumber(t) ||
           (concatenates && (t.kind() == Kind::String || t.kind() == Kind::ListOf));
  };
  bool same_kind = left.kind() == right.kind() || (isNumber(left) && isNumber(right));
  if (!operand_ok(left) || !operand_ok(right) || (!isAny(left) && !isAny(right) && !same_kind)) {
    return mismatch(node, typeList(std::vector{left, right}));
  }
  if (isAny(left) || isAny(right)) return ir::Type::any();
  if (node.op == ExprOp::Divide) return ir::Type::of(Kind::Float);
  return ir::Type::join(left, right);
}

void ExprTyper::checkDivisor(const ir::ExprNode& division) {
  const ir::ExprNode& divisor = division.operands[1];
  if (isLiteralZero(divisor)) {
    diags_.emit<DiagKind::ExprDivisionByZero>(divisor.loc, ir::exprOpText(division.op));
  }
}

ir::Type ExprTyper::call(const ir::ExprNode& node) {
  std::vector<ir::Type> arguments;
  for (const ir::ExprNode& operand : node.operands) arguments.push_back(type(operand));
  const ir::ExprFunction* function = ir::findExprFunction(node.name);
  if (!function) {
    std::vector<std::string> names{"len", "min", "max", "abs"};
    std::optional<std::string> match = closestMatch(node.name, names);
    diags_.emit<DiagKind::ExprUnknownFunction>(node.loc, node.name, ir::exprFunctionList(),
                                               didYouMean(match));
    diags_.fixIt(match);
    return ir::Type::any();
  }
  uint32_t count = static_cast<uint32_t>(arguments.size());
  if (count < function->min_args || count > function->max_args) {
    std::string expected = function->min_args == function->max_args
                               ? argumentCount(function->min_args)
                               : "at least " + argumentCount(function->min_args);
    diags_.emit<DiagKind::ExprArgumentCount>(node.loc, node.name, expected, count);
    return ir::Type::any();
  }
  if (node.name == "min" || node.name == "max") return minMax(node, arguments);
  const ir::Type& argument = arguments[0];
  if (isAny(argument)) return node.name == "len" ? ir::Type::of(Kind::Int) : ir::Type::any();
  if (node.name == "len") {
    bool sized = argument.kind() == Kind::String || argument.kind() == Kind::ListOf ||
                 argument.kind() == Kind::MapOf;
    return sized ? ir::Type::of(Kind::Int) : mismatch(node, argument.str());
  }
  return isNumber(argument) ? argument : mismatch(node, argument.str());
}

ir::Type ExprTyper::minMax(const ir::ExprNode& node, std::span<const ir::Type> arguments) {
  if (arguments.size() == 1) {
    const ir::Type& only = arguments[0];
    if (isAny(only)) return ir::Type::any();
    if (only.kind() == Kind::ListOf) return only.element();
    if (only.kind() == Kind::String) return only;
    return mismatch(node, only.str());
  }
  ir::Type result = arguments[0];
  bool numbers = true, strings = true, any = false;
  for (const ir::Type& t : arguments) {
    any = any || isAny(t);
    numbers = numbers && (isAny(t) || isNumber(t));
    strings = strings && (isAny(t) || t.kind() == Kind::String);
    result = joined(result, t);
  }
  if (!numbers && !strings) return mismatch(node, typeList(arguments));
  return any ? ir::Type::any() : result;
}

ir::Type ExprTyper::mismatch(const ir::ExprNode& node, const std::string& operands) {
  std::string_view what =
      node.op == ExprOp::Call ? std::string_view(node.name) : ir::exprOpText(node.op);
  diags_.emit<DiagKind::ExprTypeMismatch>(node.loc, what, operands);
  return ir::Type::any();
}

}  // namespace smachac::passes
