// Portable expressions: the callbacks a script writes once for every target, as a YAML tag
// (`!expr 'counter + 1'`). The frontend parses them (frontend/expr_parser.h), the pass
// check-expressions types them, and each backend writes them in its language
// (backends/expr/). Semantics are Python 3's for the operators and functions below; ints are
// 64-bit.
//
//   expr        := disjunction ['if' disjunction 'else' expr]
//   disjunction := conjunction ('or' conjunction)*
//   conjunction := inversion ('and' inversion)*
//   inversion   := 'not' inversion | comparison
//   comparison  := sum [('==' | '!=' | '<' | '<=' | '>' | '>=') sum]
//   sum         := term (('+' | '-') term)*
//   term        := factor (('*' | '/' | '//' | '%') factor)*
//   factor      := ('-' | '+') factor | primary
//   primary     := INT | FLOAT | STRING | 'True' | 'False' | NAME
//                | NAME '(' [expr (',' expr)*] ')' | '(' expr ')'
//
// A NAME is one of the state's input keys or, failing that, one of its params (whose value is
// written into the expression).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ir/support/source_loc.h"
#include "ir/value.h"

namespace smachac::ir {

enum class ExprOp : uint8_t {
  Literal,       ///< `literal`
  Name,          ///< `name`
  Negate,        ///< -a
  Plus,          ///< +a
  Not,           ///< not a
  Add,           ///< a + b
  Subtract,      ///< a - b
  Multiply,      ///< a * b
  Divide,        ///< a / b (always a float, as in Python 3)
  FloorDivide,   ///< a // b
  Modulo,        ///< a % b (the sign of b, as in Python)
  Equal,         ///< a == b
  NotEqual,      ///< a != b
  Less,          ///< a < b
  LessEqual,     ///< a <= b
  Greater,       ///< a > b
  GreaterEqual,  ///< a >= b
  And,           ///< a and b (the first false operand, else b)
  Or,            ///< a or b (the first true operand, else b)
  Conditional,   ///< operands: condition, then, else (written `then if condition else else`)
  Call,          ///< name(operands...): len, min, max, abs
};

/// The operator as written: "+", "not", "//", "if", ... ("" for literals, names and calls).
std::string_view exprOpText(ExprOp op);
bool isUnaryOp(ExprOp op);
bool isComparisonOp(ExprOp op);

struct ExprNode {
  ExprOp op = ExprOp::Literal;
  SourceLoc loc;     ///< the node's text in the script (the operator for operations)
  Value literal;     ///< Literal: an int, float, string or bool
  std::string name;  ///< Name: the key or param; Call: the function
  std::vector<ExprNode> operands;
};

/// A parsed `!expr`: its text as written and its tree.
struct PortableExpr {
  std::string text;
  ExprNode root;
};

/// The functions an expression may call, with their argument counts.
struct ExprFunction {
  std::string_view name;
  uint32_t min_args;
  uint32_t max_args;  ///< UINT32_MAX: any number
};
const ExprFunction* findExprFunction(std::string_view name);
/// "len, min, max and abs", for diagnostics.
std::string_view exprFunctionList();

/// Writes a leaf (a Literal or a Name) in the output language.
using ExprLeafWriter = std::function<std::string(const ExprNode&)>;

/// The expression in Python syntax (which is the expression language's), with parentheses
/// only where precedence needs them; `leaf` writes names and literals.
std::string printExpr(const ExprNode& node, const ExprLeafWriter& leaf);
/// The same with names as written and literals as Python writes them.
std::string printExpr(const ExprNode& node);

}  // namespace smachac::ir
