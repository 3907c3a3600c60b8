// The type rules of portable expressions (ir/expr.h), checked against the userdata types of
// the state that runs the callback. Reports, at the node concerned:
//   expr-unknown-name      a name that is neither an input key nor a param ("did you mean")
//   expr-key-not-input     a name that is userdata of the parent but no input key (a note
//                          says to add it to `input_keys`)
//   expr-unknown-function  a call of anything but len, min, max and abs
//   expr-argument-count    len and abs take one argument, min and max at least one
//   expr-type-mismatch     an operator or function applied to types Python would refuse:
//                          arithmetic on numbers (int, float), `+` also on two strings or two
//                          lists, ordering on two numbers or two strings, len on strings,
//                          lists and maps, min and max on numbers or strings (or one list)
//   expr-division-by-zero  `/`, `//` or `%` by a literal zero
// Types: int, float, string, bool, list<T>, map<string, T> and any; bool is no number here (a
// likely mistake), null and backtick values are `any`, as are keys the scope cannot type.
// Operations on `any` are checked when the callback runs.
#pragma once

#include <span>
#include <string>

#include "ir/expr.h"
#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/type.h"
#include "passes/analysis/key_types.h"

namespace smachac::passes {

class ExprTyper {
 public:
  ExprTyper(KeyTypes& key_types, DiagnosticEmitter& diags) : key_types_(key_types), diags_(diags) {}

  /// The type of `expr` run as a callback of `state`; reports every problem found.
  ir::Type check(const ir::PortableExpr& expr, const ir::State& state);

 private:
  ir::Type type(const ir::ExprNode& node);
  ir::Type name(const ir::ExprNode& node);
  ir::Type unknownName(const ir::ExprNode& node);
  ir::Type unary(const ir::ExprNode& node, const ir::Type& operand);
  ir::Type binary(const ir::ExprNode& node, const ir::Type& left, const ir::Type& right);
  ir::Type arithmetic(const ir::ExprNode& node, const ir::Type& left, const ir::Type& right);
  ir::Type call(const ir::ExprNode& node);
  ir::Type minMax(const ir::ExprNode& node, std::span<const ir::Type> arguments);
  void checkDivisor(const ir::ExprNode& division);
  ir::Type mismatch(const ir::ExprNode& node, const std::string& operands);

  KeyTypes& key_types_;
  DiagnosticEmitter& diags_;
  const ir::State* state_ = nullptr;
};

}  // namespace smachac::passes
