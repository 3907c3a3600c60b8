// Operator texts, the function table and the precedence-aware printer of portable expressions.
#include "ir/expr.h"

#include <array>
#include <limits>

#include "ir/python_text.h"

namespace smachac::ir {
namespace {

constexpr uint32_t kAnyCount = std::numeric_limits<uint32_t>::max();

constexpr std::array<ExprFunction, 4> kFunctions{{
    {"len", 1, 1},
    {"min", 1, kAnyCount},
    {"max", 1, kAnyCount},
    {"abs", 1, 1},
}};

/// Python's binding strength, weakest first (the grammar in expr.h, one level per rule).
enum Precedence : int {
  kConditional = 1,
  kOr,
  kAnd,
  kNot,
  kComparison,
  kSum,
  kTerm,
  kFactor,
  kPrimary,
};

int precedence(ExprOp op) {
  switch (op) {
    case ExprOp::Conditional:
      return kConditional;
    case ExprOp::Or:
      return kOr;
    case ExprOp::And:
      return kAnd;
    case ExprOp::Not:
      return kNot;
    case ExprOp::Add:
    case ExprOp::Subtract:
      return kSum;
    case ExprOp::Multiply:
    case ExprOp::Divide:
    case ExprOp::FloorDivide:
    case ExprOp::Modulo:
      return kTerm;
    case ExprOp::Negate:
    case ExprOp::Plus:
      return kFactor;
    case ExprOp::Literal:
    case ExprOp::Name:
    case ExprOp::Call:
      return kPrimary;
    default:
      return kComparison;
  }
}

class Printer {
 public:
  explicit Printer(const ExprLeafWriter& leaf) : leaf_(leaf) {}

  void print(const ExprNode& node, int min_precedence) {
    bool parens = precedence(node.op) < min_precedence;
    if (parens) out_ += '(';
    printNode(node);
    if (parens) out_ += ')';
  }

  std::string take() { return std::move(out_); }

 private:
  void printNode(const ExprNode& node) {
    int own = precedence(node.op);
    switch (node.op) {
      case ExprOp::Literal:
      case ExprOp::Name:
        out_ += leaf_(node);
        return;
      case ExprOp::Call:
        printCall(node);
        return;
      case ExprOp::Conditional:
        print(node.operands[1], own + 1);
        out_ += " if ";
        print(node.operands[0], own + 1);
        out_ += " else ";
        print(node.operands[2], own);
        return;
      case ExprOp::Not:
        out_ += "not ";
        print(node.operands[0], own);
        return;
      case ExprOp::Negate:
      case ExprOp::Plus:
        out_ += exprOpText(node.op);
        print(node.operands[0], own);
        return;
      default:
        printBinary(node, own);
    }
  }

  void printBinary(const ExprNode& node, int own) {
    // Left-associative; comparisons do not chain, so both their sides bind tighter.
    print(node.operands[0], isComparisonOp(node.op) ? own + 1 : own);
    out_ += ' ';
    out_ += exprOpText(node.op);
    out_ += ' ';
    print(node.operands[1], own + 1);
  }

  void printCall(const ExprNode& node) {
    out_ += node.name;
    out_ += '(';
    for (size_t i = 0; i < node.operands.size(); ++i) {
      if (i > 0) out_ += ", ";
      print(node.operands[i], kConditional);
    }
    out_ += ')';
  }

  const ExprLeafWriter& leaf_;
  std::string out_;
};

}  // namespace

std::string_view exprOpText(ExprOp op) {
  switch (op) {
    case ExprOp::Negate:
    case ExprOp::Subtract:
      return "-";
    case ExprOp::Plus:
    case ExprOp::Add:
      return "+";
    case ExprOp::Not:
      return "not";
    case ExprOp::Multiply:
      return "*";
    case ExprOp::Divide:
      return "/";
    case ExprOp::FloorDivide:
      return "//";
    case ExprOp::Modulo:
      return "%";
    case ExprOp::Equal:
      return "==";
    case ExprOp::NotEqual:
      return "!=";
    case ExprOp::Less:
      return "<";
    case ExprOp::LessEqual:
      return "<=";
    case ExprOp::Greater:
      return ">";
    case ExprOp::GreaterEqual:
      return ">=";
    case ExprOp::And:
      return "and";
    case ExprOp::Or:
      return "or";
    case ExprOp::Conditional:
      return "if";
    case ExprOp::Literal:
    case ExprOp::Name:
    case ExprOp::Call:
      return "";
  }
  return "";
}

bool isUnaryOp(ExprOp op) {
  return op == ExprOp::Negate || op == ExprOp::Plus || op == ExprOp::Not;
}

bool isComparisonOp(ExprOp op) { return precedence(op) == kComparison; }

const ExprFunction* findExprFunction(std::string_view name) {
  for (const ExprFunction& function : kFunctions) {
    if (function.name == name) return &function;
  }
  return nullptr;
}

std::string_view exprFunctionList() { return "len, min, max and abs"; }

std::string printExpr(const ExprNode& node, const ExprLeafWriter& leaf) {
  Printer printer(leaf);
  printer.print(node, kConditional);
  return printer.take();
}

std::string printExpr(const ExprNode& node) {
  return printExpr(node, [](const ExprNode& leaf) {
    return leaf.op == ExprOp::Name ? leaf.name : pythonRepr(leaf.literal);
  });
}

}  // namespace smachac::ir
