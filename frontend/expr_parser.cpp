// Recursive descent over the grammar of ir/expr.h. Each parse function parses one rule; the
// first error stops the parse (an expression is one line of a script: one error is enough).
#include "frontend/expr_parser.h"

#include <fmt/core.h>

#include <optional>

#include "ir/support/python_keywords.h"

namespace smachac::frontend {
namespace {

using ir::ExprNode;
using ir::ExprOp;

/// Nesting deeper than this is refused (the parser recurses once per level).
constexpr int kMaxDepth = 200;

struct BinaryOp {
  std::string_view text;
  ExprOp op;
};

constexpr BinaryOp kSumOps[] = {{"+", ExprOp::Add}, {"-", ExprOp::Subtract}};
constexpr BinaryOp kTermOps[] = {{"*", ExprOp::Multiply},
                                 {"/", ExprOp::Divide},
                                 {"//", ExprOp::FloorDivide},
                                 {"%", ExprOp::Modulo}};
constexpr BinaryOp kComparisonOps[] = {{"==", ExprOp::Equal},  {"!=", ExprOp::NotEqual},
                                       {"<", ExprOp::Less},    {"<=", ExprOp::LessEqual},
                                       {">", ExprOp::Greater}, {">=", ExprOp::GreaterEqual}};

class Parser {
 public:
  Parser(std::vector<ExprToken> tokens, const ExprLocator& locate)
      : tokens_(std::move(tokens)), locate_(locate) {}

  std::optional<ExprNode> run() {
    if (peek().kind == ExprTokenKind::End) return fail("empty expression", peek());
    std::optional<ExprNode> node = expr();
    if (!node) return std::nullopt;
    if (peek().kind != ExprTokenKind::End) return unexpected("an operator or the end");
    return node;
  }

  const std::optional<ExprSyntaxError>& error() const { return error_; }

 private:
  // expr := disjunction ['if' disjunction 'else' expr]
  std::optional<ExprNode> expr() {
    if (++depth_ > kMaxDepth) return fail("expression nested too deeply", peek());
    std::optional<ExprNode> then = disjunction();
    if (then && isKeyword("if")) then = conditional(std::move(*then));
    --depth_;
    return then;
  }

  std::optional<ExprNode> conditional(ExprNode then) {
    ExprNode node = operation(ExprOp::Conditional, take());
    std::optional<ExprNode> condition = disjunction();
    if (!condition) return std::nullopt;
    if (!isKeyword("else")) return unexpected("`else`");
    take();
    std::optional<ExprNode> otherwise = expr();
    if (!otherwise) return std::nullopt;
    node.operands = {std::move(*condition), std::move(then), std::move(*otherwise)};
    return node;
  }

  // disjunction := conjunction ('or' conjunction)*
  std::optional<ExprNode> disjunction() {
    return keywordChain("or", ExprOp::Or, &Parser::conjunction);
  }

  // conjunction := inversion ('and' inversion)*
  std::optional<ExprNode> conjunction() {
    return keywordChain("and", ExprOp::And, &Parser::inversion);
  }

  // inversion := 'not' inversion | comparison
  std::optional<ExprNode> inversion() {
    if (!isKeyword("not")) return comparison();
    ExprNode node = operation(ExprOp::Not, take());
    if (++depth_ > kMaxDepth) return fail("expression nested too deeply", peek());
    std::optional<ExprNode> operand = inversion();
    --depth_;
    if (!operand) return std::nullopt;
    node.operands.push_back(std::move(*operand));
    return node;
  }

  // comparison := sum [compare_op sum]; comparisons do not chain
  std::optional<ExprNode> comparison() {
    std::optional<ExprNode> left = sum();
    if (!left) return std::nullopt;
    const BinaryOp* op = findOperator(kComparisonOps);
    if (!op) return left;
    ExprNode node = operation(op->op, take());
    std::optional<ExprNode> right = sum();
    if (!right) return std::nullopt;
    if (findOperator(kComparisonOps)) {
      return fail(
          fmt::format("comparisons do not chain: write `a {} b and b {} c`", op->text, peek().text),
          peek());
    }
    node.operands = {std::move(*left), std::move(*right)};
    return node;
  }

  // sum := term (('+' | '-') term)*
  std::optional<ExprNode> sum() { return operatorChain(kSumOps, &Parser::term); }

  // term := factor (('*' | '/' | '//' | '%') factor)*
  std::optional<ExprNode> term() { return operatorChain(kTermOps, &Parser::factor); }

  // factor := ('-' | '+') factor | primary
  std::optional<ExprNode> factor() {
    if (!isOperator("-") && !isOperator("+")) return primary();
    ExprOp op = isOperator("-") ? ExprOp::Negate : ExprOp::Plus;
    ExprNode node = operation(op, take());
    if (++depth_ > kMaxDepth) return fail("expression nested too deeply", peek());
    std::optional<ExprNode> operand = factor();
    --depth_;
    if (!operand) return std::nullopt;
    node.operands.push_back(std::move(*operand));
    return node;
  }

  // primary := INT | FLOAT | STRING | 'True' | 'False' | NAME | NAME '(' args ')' | '(' expr ')'
  std::optional<ExprNode> primary() {
    const ExprToken& token = peek();
    switch (token.kind) {
      case ExprTokenKind::Number:
      case ExprTokenKind::String:
        return literal(take().value);
      case ExprTokenKind::Name:
        return name();
      case ExprTokenKind::Operator:
        if (token.text == "(") return parenthesised();
        [[fallthrough]];
      case ExprTokenKind::End:
        return unexpected("an operand");
    }
    return std::nullopt;
  }

  std::optional<ExprNode> literal(ir::Value value) {
    ExprNode node;
    node.op = ExprOp::Literal;
    node.loc = locate(tokens_[pos_ - 1]);
    node.literal = std::move(value);
    return node;
  }

  std::optional<ExprNode> name() {
    const ExprToken& token = take();
    if (token.text == "True" || token.text == "False") {
      return literal(ir::Value::boolean(token.text == "True"));
    }
    if (isPythonKeyword(token.text)) {
      return fail(fmt::format("`{}` is not part of the expression language", token.text), token);
    }
    ExprNode node;
    node.op = isOperator("(") ? ExprOp::Call : ExprOp::Name;
    node.loc = locate(token);
    node.name = std::string(token.text);
    if (node.op == ExprOp::Call && !arguments(node)) return std::nullopt;
    return node;
  }

  // args := [expr (',' expr)*] ')'   (after the '(')
  bool arguments(ExprNode& call) {
    take();
    while (!isOperator(")")) {
      if (!call.operands.empty()) {
        if (!isOperator(",")) return unexpected("`,` or `)`").has_value();
        take();
      }
      std::optional<ExprNode> argument = expr();
      if (!argument) return false;
      call.operands.push_back(std::move(*argument));
    }
    take();
    return true;
  }

  std::optional<ExprNode> parenthesised() {
    take();
    std::optional<ExprNode> inner = expr();
    if (!inner) return std::nullopt;
    if (!isOperator(")")) {
      return unexpected("`)`");
    }
    take();
    return inner;
  }

  using Rule = std::optional<ExprNode> (Parser::*)();

  std::optional<ExprNode> keywordChain(std::string_view keyword, ExprOp op, Rule operand) {
    std::optional<ExprNode> left = (this->*operand)();
    while (left && isKeyword(keyword)) {
      ExprNode node = operation(op, take());
      std::optional<ExprNode> right = (this->*operand)();
      if (!right) return std::nullopt;
      node.operands = {std::move(*left), std::move(*right)};
      left = std::move(node);
    }
    return left;
  }

  template <size_t N>
  std::optional<ExprNode> operatorChain(const BinaryOp (&ops)[N], Rule operand) {
    std::optional<ExprNode> left = (this->*operand)();
    while (left) {
      const BinaryOp* op = findOperator(ops);
      if (!op) break;
      ExprNode node = operation(op->op, take());
      std::optional<ExprNode> right = (this->*operand)();
      if (!right) return std::nullopt;
      node.operands = {std::move(*left), std::move(*right)};
      left = std::move(node);
    }
    return left;
  }

  template <size_t N>
  const BinaryOp* findOperator(const BinaryOp (&ops)[N]) const {
    if (peek().kind != ExprTokenKind::Operator) return nullptr;
    for (const BinaryOp& op : ops) {
      if (op.text == peek().text) return &op;
    }
    return nullptr;
  }

  ExprNode operation(ExprOp op, const ExprToken& token) const {
    ExprNode node;
    node.op = op;
    node.loc = locate(token);
    return node;
  }

  bool isKeyword(std::string_view word) const {
    return peek().kind == ExprTokenKind::Name && peek().text == word;
  }
  bool isOperator(std::string_view text) const {
    return peek().kind == ExprTokenKind::Operator && peek().text == text;
  }
  const ExprToken& peek() const { return tokens_[pos_]; }
  const ExprToken& take() { return tokens_[pos_ < tokens_.size() - 1 ? pos_++ : pos_]; }

  SourceLoc locate(const ExprToken& token) const {
    return locate_(token.offset, std::max<uint32_t>(token.length, 1));
  }

  std::optional<ExprNode> unexpected(const std::string& expected) {
    const ExprToken& token = peek();
    if (token.kind == ExprTokenKind::End) {
      return fail(fmt::format("expected {}, found the end of the expression", expected), token);
    }
    if (token.text == "=") {
      return fail("`=` assigns nothing here: compare with `==`", token);
    }
    return fail(fmt::format("expected {}, found `{}`", expected, token.text), token);
  }

  std::optional<ExprNode> fail(std::string message, const ExprToken& token) {
    if (!error_) {
      error_ =
          ExprSyntaxError{std::move(message), token.offset, std::max<uint32_t>(token.length, 1)};
    }
    return std::nullopt;
  }

  std::vector<ExprToken> tokens_;
  const ExprLocator& locate_;
  size_t pos_ = 0;
  int depth_ = 0;
  std::optional<ExprSyntaxError> error_;
};

}  // namespace

std::variant<std::shared_ptr<const ir::PortableExpr>, ExprSyntaxError> parseExpr(
    std::string_view text, const ExprLocator& locate) {
  // The tokens before a lexical error are parsed too: a parse error there comes first.
  ExprTokens lexed = lexExpr(text);
  uint32_t lexed_until = lexed.tokens.back().offset;
  Parser parser(std::move(lexed.tokens), locate);
  std::optional<ExprNode> root = parser.run();
  if (lexed.error && (root || parser.error()->offset >= lexed_until)) return *lexed.error;
  if (!root) return *parser.error();
  return std::make_shared<const ir::PortableExpr>(
      ir::PortableExpr{std::string(text), std::move(*root)});
}

}  // namespace smachac::frontend
