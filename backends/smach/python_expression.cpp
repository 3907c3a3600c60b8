// pythonExpressionError (python_expression.h): a recursive-descent recogniser of Python 3's
// expression grammar. Each function recognises the rule it is named after (the names of
// Python's own grammar) and throws Unexpected at the first token that does not fit.
#include "backends/smach/python_expression.h"

#include "backends/smach/python_tokens.h"

namespace smachac::backends {
namespace {

struct Unexpected {
  size_t offset;
  std::string message;
};

// How deeply the recursive rules may nest: each of the 200 brackets the tokenizer allows
// (CPython's limit) nests three, and chains of unary operators, `not`, `lambda` or
// conditional expressions nest one a link.
constexpr int kMaxDepth = 1000;

class Recogniser {
 public:
  explicit Recogniser(const std::vector<PythonToken>& tokens) : tokens_(tokens) {}

  // eval_input: expression (',' expression)* [','] END
  void evalInput() {
    expression();
    while (accept(",")) {
      if (peek().kind == PythonTokenKind::End) break;
      expression();
    }
    if (peek().kind != PythonTokenKind::End) unexpected();
  }

 private:
  const PythonToken& peek(size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }

  bool is(std::string_view text, size_t ahead = 0) const {
    const PythonToken& token = peek(ahead);
    return (token.kind == PythonTokenKind::Operator || token.kind == PythonTokenKind::Keyword) &&
           token.text == text;
  }

  bool accept(std::string_view text) {
    if (!is(text)) return false;
    ++pos_;
    return true;
  }

  void expect(std::string_view text) {
    if (!accept(text)) unexpected("expected `" + std::string(text) + "`");
  }

  [[noreturn]] void unexpected(std::string expected = {}) const {
    const PythonToken& token = peek();
    std::string message = token.kind == PythonTokenKind::End
                              ? "unexpected end of the code"
                              : "unexpected `" + std::string(token.text) + "`";
    if (!expected.empty()) message += " (" + expected + ")";
    throw Unexpected{token.offset, message};
  }

  // Where an expression may end: a closing bracket, a separator or the end.
  bool atExpressionEnd() const {
    return peek().kind == PythonTokenKind::End || is(")") || is("]") || is("}") || is(",") ||
           is(":") || is("=") || is("for") || is("async") || is("if") || is("else") || is("in");
  }

  // star_expressions: star_expression (',' star_expression)* [',']
  void starExpressions() {
    starExpression();
    while (accept(",")) {
      if (atExpressionEnd()) return;
      starExpression();
    }
  }

  // star_expression: '*' bitwise_or | expression
  void starExpression() {
    if (accept("*")) return bitwiseOr();
    expression();
  }

  // star_named_expression: '*' bitwise_or | named_expression
  void starNamedExpression() {
    if (accept("*")) return bitwiseOr();
    namedExpression();
  }

  // named_expression: NAME ':=' expression | expression
  void namedExpression() {
    if (peek().kind == PythonTokenKind::Name && is(":=", 1)) {
      pos_ += 2;
      return expression();
    }
    expression();
  }

  // Counts the nesting of the rules that recurse (expression, inversion, factor).
  class Nested {
   public:
    explicit Nested(Recogniser& recogniser) : recogniser_(recogniser) {
      if (++recogniser_.depth_ > kMaxDepth) {
        throw Unexpected{recogniser_.peek().offset, "the expression is nested too deeply"};
      }
    }
    ~Nested() { --recogniser_.depth_; }
    Nested(const Nested&) = delete;
    Nested& operator=(const Nested&) = delete;

   private:
    Recogniser& recogniser_;
  };

  // expression: lambdef | disjunction ['if' disjunction 'else' expression]
  void expression() {
    Nested nested(*this);
    if (accept("lambda")) return lambdef();
    disjunction();
    if (accept("if")) {
      disjunction();
      expect("else");
      expression();
    }
  }

  // lambdef: 'lambda' [lambda_params] ':' expression
  void lambdef() {
    if (!is(":")) lambdaParams();
    expect(":");
    expression();
  }

  // lambda_params: a comma-separated list of NAME ['=' expression], '*' [NAME], '**' NAME
  // and '/', with an optional trailing comma.
  void lambdaParams() {
    bool bare_star = false;  // a `*` without a name needs a named parameter after it
    do {
      if (is(":")) break;
      if (accept("/")) continue;
      if (accept("**")) {
        name();
      } else if (accept("*")) {
        bare_star = peek().kind != PythonTokenKind::Name;
        if (!bare_star) name();
      } else {
        name();
        bare_star = false;
        if (accept("=")) expression();
      }
    } while (accept(","));
    if (bare_star) unexpected("a bare `*` needs a named parameter after it");
  }

  void name() {
    if (peek().kind != PythonTokenKind::Name) unexpected("expected a name");
    ++pos_;
  }

  // disjunction: conjunction ('or' conjunction)*; conjunction: inversion ('and' inversion)*
  void disjunction() {
    conjunction();
    while (accept("or")) conjunction();
  }

  void conjunction() {
    inversion();
    while (accept("and")) inversion();
  }

  // inversion: 'not' inversion | comparison
  void inversion() {
    Nested nested(*this);
    if (accept("not")) return inversion();
    comparison();
  }

  // comparison: bitwise_or (compare_op bitwise_or)*
  void comparison() {
    bitwiseOr();
    while (compareOperator()) bitwiseOr();
  }

  bool compareOperator() {
    for (std::string_view op : {"==", "!=", "<=", ">=", "<", ">", "in"}) {
      if (accept(op)) return true;
    }
    if (is("not") && is("in", 1)) {
      pos_ += 2;
      return true;
    }
    if (accept("is")) {
      accept("not");
      return true;
    }
    return false;
  }

  // The binary operators from `|` down to `*`, each level left-associative.
  void bitwiseOr() { binary(0); }

  void binary(size_t level) {
    static constexpr std::string_view kLevels[][5] = {
        {"|"}, {"^"}, {"&"}, {"<<", ">>"}, {"+", "-"}, {"*", "/", "//", "%", "@"}};
    constexpr size_t kCount = sizeof kLevels / sizeof kLevels[0];
    auto operand = [&] { level + 1 < kCount ? binary(level + 1) : factor(); };
    operand();
    while (acceptAny(kLevels[level])) operand();
  }

  template <size_t N>
  bool acceptAny(const std::string_view (&operators)[N]) {
    for (std::string_view op : operators) {
      if (!op.empty() && accept(op)) return true;
    }
    return false;
  }

  // factor: ('+' | '-' | '~') factor | power; power: await_primary ['**' factor]
  void factor() {
    Nested nested(*this);
    if (accept("+") || accept("-") || accept("~")) return factor();
    accept("await");
    primary();
    if (accept("**")) factor();
  }

  // primary: atom ('.' NAME | '(' [arguments] ')' | '[' slices ']')*
  void primary() {
    atom();
    for (;;) {
      if (accept(".")) {
        name();
      } else if (accept("(")) {
        if (!accept(")")) {
          arguments();
          expect(")");
        }
      } else if (accept("[")) {
        slices();
        expect("]");
      } else {
        return;
      }
    }
  }

  // arguments: positional and `*` arguments, then keyword and `*` arguments, then keyword
  // and `**` arguments, separated by commas; or a single generator expression.
  enum class ArgumentPhase { Positional, Keyword, DoubleStarred };

  void arguments() {
    ArgumentPhase phase = ArgumentPhase::Positional;
    argument(true, phase);
    while (accept(",")) {
      if (is(")")) return;
      argument(false, phase);
    }
  }

  void argument(bool first, ArgumentPhase& phase) {
    const PythonToken& start = peek();
    if (accept("**")) {
      phase = ArgumentPhase::DoubleStarred;
      return expression();
    }
    if (accept("*")) {
      if (phase == ArgumentPhase::DoubleStarred) {
        throw Unexpected{start.offset, "`*` argument after a `**` argument"};
      }
      return expression();
    }
    if (peek().kind == PythonTokenKind::Name && is("=", 1)) {
      pos_ += 2;
      if (phase == ArgumentPhase::Positional) phase = ArgumentPhase::Keyword;
      return expression();
    }
    if (phase != ArgumentPhase::Positional) {
      throw Unexpected{start.offset, "positional argument after a keyword argument"};
    }
    namedExpression();
    if (first && (is("for") || is("async"))) {
      forIfClauses();
      if (!is(")")) unexpected("a generator argument must be the only one");
    }
  }

  // slices: slice (',' slice)* [','];  slice: [expr] ':' [expr] [':' [expr]] | named_expr
  void slices() {
    slice();
    while (accept(",")) {
      if (is("]")) return;
      slice();
    }
  }

  void slice() {
    if (accept("*")) return expression();
    if (!is(":")) {
      namedExpression();
      if (!is(":")) return;
    }
    expect(":");
    if (!is(":") && !is("]") && !is(",")) expression();
    if (accept(":") && !is("]") && !is(",")) expression();
  }

  // atom: NAME | True | False | None | strings | NUMBER | '...' | group, tuple or genexp |
  // list or listcomp | dict, set or their comprehensions
  void atom() {
    const PythonToken& token = peek();
    if (token.kind == PythonTokenKind::Name || token.kind == PythonTokenKind::Number) {
      ++pos_;
      return;
    }
    if (token.kind == PythonTokenKind::String) {
      while (peek().kind == PythonTokenKind::String) ++pos_;  // adjacent strings concatenate
      return;
    }
    if (accept("True") || accept("False") || accept("None") || accept("...")) return;
    if (accept("(")) return parenthesised();
    if (accept("[")) return bracketed("]");
    if (accept("{")) return braced();
    unexpected();
  }

  // '(' ')' | '(' yield_expr ')' | '(' star_named_expressions ')' | '(' genexp ')'
  void parenthesised() {
    if (accept(")")) return;
    if (accept("yield")) {
      if (accept("from")) {
        expression();
      } else if (!is(")")) {
        starExpressions();
      }
      return expect(")");
    }
    bracketed(")");
  }

  // A list display, a tuple or a group, or a comprehension of one element. A group holds no
  // starred expression: `(*x)` is an error, `(*x,)` a tuple.
  void bracketed(std::string_view close) {
    if (accept(close)) return;
    const PythonToken& first = peek();
    starNamedExpression();
    if (is("for") || is("async")) {
      forIfClauses();
      return expect(close);
    }
    if (close == ")" && first.text == "*" && first.kind == PythonTokenKind::Operator && is(")")) {
      throw Unexpected{first.offset, "a starred expression in parentheses needs a comma"};
    }
    while (accept(",")) {
      if (is(close)) break;
      starNamedExpression();
    }
    expect(close);
  }

  // '{' '}' | a dict display or comprehension | a set display or comprehension
  void braced() {
    if (accept("}")) return;
    if (accept("**")) {
      bitwiseOr();
      return dictRest();
    }
    starNamedExpression();
    if (accept(":")) {
      expression();
      if (is("for") || is("async")) {
        forIfClauses();
        return expect("}");
      }
      return dictRest();
    }
    if (is("for") || is("async")) {
      forIfClauses();
      return expect("}");
    }
    while (accept(",")) {
      if (is("}")) break;
      starNamedExpression();
    }
    expect("}");
  }

  // (',' ('**' bitwise_or | expression ':' expression))* [','] '}'
  void dictRest() {
    while (accept(",")) {
      if (is("}")) break;
      if (accept("**")) {
        bitwiseOr();
      } else {
        expression();
        expect(":");
        expression();
      }
    }
    expect("}");
  }

  // for_if_clauses: (['async'] 'for' star_targets 'in' disjunction ('if' disjunction)*)+
  void forIfClauses() {
    while (is("for") || is("async")) {
      accept("async");
      expect("for");
      starTargets();
      expect("in");
      disjunction();
      while (accept("if")) disjunction();
    }
  }

  // star_targets: ['*'] target (',' ['*'] target)* [','], a target read as an operand
  void starTargets() {
    accept("*");
    bitwiseOr();
    while (accept(",")) {
      if (is("in")) return;
      accept("*");
      bitwiseOr();
    }
  }

  const std::vector<PythonToken>& tokens_;
  size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

std::optional<PythonSyntaxError> pythonExpressionError(std::string_view code) {
  const PythonTokens tokens = tokenizePython(code);
  if (tokens.error) return PythonSyntaxError{tokens.error->offset, tokens.error->message};
  try {
    Recogniser(tokens.tokens).evalInput();
  } catch (const Unexpected& error) {
    return PythonSyntaxError{error.offset, error.message};
  }
  return std::nullopt;
}

}  // namespace smachac::backends
