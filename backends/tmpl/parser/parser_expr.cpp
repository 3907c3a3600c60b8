// Expression parsing (Jinja2 precedence, lowest first): conditional `a if c else b`, `or`,
// `and`, `not`, comparisons and `in`, `+ -`, `~`, `* / // %`, `**` (left-associative), unary
// `- +`, then primaries with postfix `.attr`, `[index]`, calls, `|filter` and `is test`.
#include <charconv>
#include <cmath>

#include "backends/tmpl/error.h"
#include "backends/tmpl/parser/parser.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

constexpr int kMaxNesting = 100;

bool isCompareToken(Tok kind, CmpOp& op) {
  static constexpr std::pair<Tok, CmpOp> kOps[] = {
      {Tok::Eq, CmpOp::Eq}, {Tok::Ne, CmpOp::Ne}, {Tok::Lt, CmpOp::Lt},
      {Tok::Le, CmpOp::Le}, {Tok::Gt, CmpOp::Gt}, {Tok::Ge, CmpOp::Ge},
  };
  for (const auto& [tok, cmp] : kOps) {
    if (tok == kind) {
      op = cmp;
      return true;
    }
  }
  return false;
}

}  // namespace

NestingGuard::NestingGuard(Parser& parser, uint32_t pos) : parser_(parser) {
  if (++parser_.nesting_ > kMaxNesting) [[unlikely]] {
    --parser_.nesting_;
    failTooDeep(pos);
  }
}

// Out of line, so that the guards that pass do not pay for building the message.
void NestingGuard::failTooDeep(uint32_t pos) const {
  parser_.failAt(pos, "template nested too deeply (limit " + std::to_string(kMaxNesting) + ")");
}

// expression := cond_expr | or_expr   (see with_cond_expr)
Expr* Parser::parseExpression(bool with_cond_expr) {
  NestingGuard guard(*this, current().pos);
  if (atLoneOperand()) {
    // What the descent through every level would give, nested as deep (parseUnary's guard).
    NestingGuard unary_guard(*this, current().pos);
    return parsePrimary();
  }
  return with_cond_expr ? parseCondExpr() : parseOr();
}

// A name other than `not`, a string or a number, followed by a token that ends an
// expression: no operator, postfix, filter or test can apply to it.
bool Parser::atLoneOperand() const {
  const Token& token = current();
  bool operand = token.is(Tok::String) || token.is(Tok::Integer) || token.is(Tok::Float) ||
                 (token.is(Tok::Name) && textOf(token) != "not");
  if (!operand) return false;
  switch (peek().kind) {
    case Tok::VariableEnd:
    case Tok::BlockEnd:
    case Tok::Comma:
    case Tok::RParen:
    case Tok::RBracket:
    case Tok::RBrace:
    case Tok::Colon:
      return true;
    default:
      return false;
  }
}

// cond_expr := or_expr ("if" or_expr ["else" cond_expr])*
Expr* Parser::parseCondExpr() {
  uint32_t pos = current().pos;
  Expr* expr = parseOr();
  while (skipName("if")) {
    Expr* test = parseOr();
    Expr* otherwise = skipName("else") ? parseCondExpr() : nullptr;
    expr = arena_.make<CondExpr>(pos, test, expr, otherwise);
    pos = current().pos;
  }
  return expr;
}

// `operand (word operand)*` as left-nested `and`/`or` nodes.
Expr* Parser::parseLogic(ExprKind kind, std::string_view word, Expr* (Parser::*operand)()) {
  Expr* left = (this->*operand)();
  while (isName(current(), word)) {
    uint32_t pos = next().pos;
    left = arena_.make<BinaryExpr>(kind, pos, BinOp::Add, left, (this->*operand)());
  }
  return left;
}

// or_expr := and_expr ("or" and_expr)*
Expr* Parser::parseOr() { return parseLogic(ExprKind::Or, "or", &Parser::parseAnd); }

// and_expr := not_expr ("and" not_expr)*
Expr* Parser::parseAnd() { return parseLogic(ExprKind::And, "and", &Parser::parseNot); }

// not_expr := "not" not_expr | compare
Expr* Parser::parseNot() {
  if (isName(current(), "not")) {
    NestingGuard guard(*this, current().pos);
    uint32_t pos = next().pos;
    return arena_.make<UnaryExpr>(ExprKind::Not, pos, parseNot());
  }
  return parseCompare();
}

// compare := math1 (("==" | "!=" | "<" | "<=" | ">" | ">=" | "in" | "not" "in") math1)*
Expr* Parser::parseCompare() {
  Expr* expr = parseMath1();
  CompareExpr* compare = nullptr;
  while (true) {
    CmpOp op;
    uint32_t pos = current().pos;
    if (isCompareToken(current().kind, op)) {
      next();
    } else if (skipName("in")) {
      op = CmpOp::In;
    } else if (isName(current(), "not") && isName(peek(), "in")) {
      next();
      next();
      op = CmpOp::NotIn;
    } else {
      break;
    }
    if (!compare) compare = arena_.make<CompareExpr>(pos, expr);
    compare->ops.emplace_back(op, parseMath1());
  }
  return compare ? compare : expr;
}

// math1 := concat (("+" | "-") concat)*
Expr* Parser::parseMath1() {
  Expr* left = parseConcat();
  while (current().is(Tok::Add) || current().is(Tok::Sub)) {
    BinOp op = current().is(Tok::Add) ? BinOp::Add : BinOp::Sub;
    uint32_t pos = next().pos;
    left = arena_.make<BinaryExpr>(ExprKind::Binary, pos, op, left, parseConcat());
  }
  return left;
}

// concat := math2 ("~" math2)*
Expr* Parser::parseConcat() {
  Expr* first = parseMath2();
  if (!current().is(Tok::Tilde)) return first;
  auto* concat = arena_.make<ConcatExpr>(current().pos);
  concat->items.push_back(first);
  while (skipIf(Tok::Tilde)) concat->items.push_back(parseMath2());
  return concat;
}

// math2 := pow (("*" | "/" | "//" | "%") pow)*
Expr* Parser::parseMath2() {
  Expr* left = parsePow();
  while (true) {
    BinOp op;
    switch (current().kind) {
      case Tok::Mul:
        op = BinOp::Mul;
        break;
      case Tok::Div:
        op = BinOp::Div;
        break;
      case Tok::FloorDiv:
        op = BinOp::FloorDiv;
        break;
      case Tok::Mod:
        op = BinOp::Mod;
        break;
      default:
        return left;
    }
    uint32_t pos = next().pos;
    left = arena_.make<BinaryExpr>(ExprKind::Binary, pos, op, left, parsePow());
  }
}

// pow := unary ("**" unary)*   -- left-associative, as in Jinja2
Expr* Parser::parsePow() {
  Expr* left = parseUnary(UnaryFilters::Parse);
  while (current().is(Tok::Pow)) {
    uint32_t pos = next().pos;
    left = arena_.make<BinaryExpr>(ExprKind::Binary, pos, BinOp::Pow, left,
                                   parseUnary(UnaryFilters::Parse));
  }
  return left;
}

// unary := ("-" | "+") unary_no_filters postfix* filters? | primary postfix* filters?
Expr* Parser::parseUnary(UnaryFilters filters) {
  NestingGuard guard(*this, current().pos);
  Expr* node;
  if (current().is(Tok::Sub) || current().is(Tok::Add)) {
    ExprKind kind = current().is(Tok::Sub) ? ExprKind::Neg : ExprKind::Pos;
    uint32_t pos = next().pos;
    node = arena_.make<UnaryExpr>(kind, pos, parseUnary(UnaryFilters::Leave));
  } else {
    node = parsePrimary();
  }
  node = parsePostfix(node);
  return filters == UnaryFilters::Parse ? parseFilterExpr(node) : node;
}

// primary := NAME | "true" | "false" | "none" (either case) | STRING+ | INTEGER | FLOAT
//          | "(" tuple_in_parens ")" | list | dict
Expr* Parser::parsePrimary() {
  const Token& token = current();
  switch (token.kind) {
    case Tok::Name: {
      next();
      if (textOf(token) == "true" || textOf(token) == "True") {
        return arena_.make<ConstExpr>(token.pos, Value::boolean(true));
      }
      if (textOf(token) == "false" || textOf(token) == "False") {
        return arena_.make<ConstExpr>(token.pos, Value::boolean(false));
      }
      if (textOf(token) == "none" || textOf(token) == "None") {
        return arena_.make<ConstExpr>(token.pos, Value::none());
      }
      return arena_.make<NameExpr>(token.pos, name(textOf(token)), NameCtx::Load);
    }
    case Tok::String:
      return parseStringLiteral();
    case Tok::Integer:
    case Tok::Float:
      return parseNumber(next());
    case Tok::LParen: {
      NestingGuard guard(*this, token.pos);
      next();
      Expr* node = parseTuple({.explicit_parens = true});
      expect(Tok::RParen);
      return node;
    }
    case Tok::LBracket:
      return parseList();
    case Tok::LBrace:
      return parseDict();
    default:
      failGot(token, "unexpected ");
  }
}

// strings := STRING+   -- adjacent literals concatenate
Expr* Parser::parseStringLiteral() {
  uint32_t pos = current().pos;
  std::string text;
  while (current().is(Tok::String)) {
    const Token& token = next();
    text += unescapeString(textOf(token).substr(1, textOf(token).size() - 2), token.pos);
  }
  return arena_.make<ConstExpr>(pos, Value::string(std::move(text)));
}

// number := INTEGER | FLOAT   -- `_` separators, 0x/0o/0b prefixes
Expr* Parser::parseNumber(const Token& token) {
  std::string digits;
  for (char c : textOf(token)) {
    if (c != '_') digits.push_back(c);
  }
  if (token.is(Tok::Float)) {
    double d = 0;
    auto result = std::from_chars(digits.data(), digits.data() + digits.size(), d);
    if (result.ec == std::errc::result_out_of_range) {
      size_t e = digits.find_first_of("eE");
      bool negative_exponent = e != std::string::npos && digits[e + 1] == '-';
      d = negative_exponent ? 0.0 : HUGE_VAL;
    }
    return arena_.make<ConstExpr>(token.pos, Value::real(d));
  }
  int base = 10;
  size_t start = 0;
  if (digits.size() > 2 && digits[0] == '0') {
    char b = static_cast<char>(digits[1] | 0x20);
    base = b == 'x' ? 16 : b == 'o' ? 8 : b == 'b' ? 2 : 10;
    if (base != 10) start = 2;
  }
  int64_t value = 0;
  auto result = std::from_chars(digits.data() + start, digits.data() + digits.size(), value, base);
  if (result.ec != std::errc()) failAt(token.pos, "integer literal is too large");
  return arena_.make<ConstExpr>(token.pos, Value::integer(value));
}

// tuple_end := "}}" | "%}" | ")" | one of extra_end
bool Parser::isTupleEnd(std::initializer_list<std::string_view> extra_end) const {
  const Token& t = current();
  if (t.is(Tok::VariableEnd) || t.is(Tok::BlockEnd) || t.is(Tok::RParen)) return true;
  for (std::string_view name : extra_end) {
    if (isName(t, name)) return true;
  }
  return false;
}

// tuple := item ("," item)* [","]   -- one item without a comma is that item
// item := expression | or_expr (tuple_no_cond) | primary (target_tuple, simplified)
Expr* Parser::parseTuple(const TupleOptions& options) {
  uint32_t pos = current().pos;
  auto item = [&] {
    return options.simplified ? parsePrimary() : parseExpression(options.with_cond_expr);
  };
  std::vector<Expr*> items;
  if (!isTupleEnd(options.extra_end)) {
    Expr* first = item();
    if (!current().is(Tok::Comma)) return first;  // one expression: no list of items made
    items.push_back(first);
    while (current().is(Tok::Comma)) {
      next();
      if (isTupleEnd(options.extra_end)) break;
      items.push_back(item());
    }
  } else if (!options.explicit_parens) {
    failGot(current(), "expected an expression, got ");
  }
  auto* tuple = arena_.make<SeqExpr>(ExprKind::Tuple, pos);
  tuple->items = std::move(items);
  return tuple;
}

// list := "[" [expression ("," expression)* [","]] "]"
Expr* Parser::parseList() {
  NestingGuard guard(*this, current().pos);
  auto* list = arena_.make<SeqExpr>(ExprKind::List, expect(Tok::LBracket).pos);
  while (!current().is(Tok::RBracket)) {
    if (!list->items.empty()) expect(Tok::Comma);
    if (current().is(Tok::RBracket)) break;
    list->items.push_back(parseExpression());
  }
  expect(Tok::RBracket);
  return list;
}

// dict := "{" [expression ":" expression ("," expression ":" expression)* [","]] "}"
Expr* Parser::parseDict() {
  NestingGuard guard(*this, current().pos);
  auto* dict = arena_.make<DictExpr>(expect(Tok::LBrace).pos);
  while (!current().is(Tok::RBrace)) {
    if (!dict->items.empty()) expect(Tok::Comma);
    if (current().is(Tok::RBrace)) break;
    Expr* key = parseExpression();
    expect(Tok::Colon);
    dict->items.emplace_back(key, parseExpression());
  }
  expect(Tok::RBrace);
  return dict;
}

// call := callee call_args
Expr* Parser::parseCall(Expr* callee) {
  auto* call = arena_.make<CallExpr>(callee->pos, callee);
  call->args = parseCallArgs();
  return call;
}

// postfix := subscript | call_args
Expr* Parser::parsePostfix(Expr* node) {
  while (true) {
    if (current().is(Tok::Dot) || current().is(Tok::LBracket)) {
      node = parseSubscript(node);
    } else if (current().is(Tok::LParen)) {
      node = parseCall(node);
    } else {
      return node;
    }
  }
}

// filters := (filter_chain | test | call_args)*
Expr* Parser::parseFilterExpr(Expr* node) {
  while (true) {
    if (current().is(Tok::Pipe)) {
      node = parseFilterChain(node, FilterStart::AtPipe);
    } else if (isName(current(), "is")) {
      node = parseTest(node);
    } else if (current().is(Tok::LParen)) {
      node = parseCall(node);
    } else {
      return node;
    }
  }
}

// subscript := "." NAME | "." INTEGER | "[" subscribed ("," subscribed)* "]"
Expr* Parser::parseSubscript(Expr* node) {
  NestingGuard guard(*this, current().pos);
  const Token& token = next();
  if (token.is(Tok::Dot)) {
    const Token& attr = next();
    if (attr.is(Tok::Name)) return arena_.make<GetattrExpr>(attr.pos, node, name(textOf(attr)));
    if (!attr.is(Tok::Integer)) failAt(attr.pos, "expected name or number after `.`");
    return arena_.make<GetitemExpr>(attr.pos, node, parseNumber(attr));
  }
  std::vector<Expr*> args;
  while (!current().is(Tok::RBracket)) {
    if (!args.empty()) expect(Tok::Comma);
    args.push_back(parseSubscribed());
  }
  expect(Tok::RBracket);
  if (args.size() == 1) return arena_.make<GetitemExpr>(token.pos, node, args[0]);
  auto* tuple = arena_.make<SeqExpr>(ExprKind::Tuple, token.pos);
  tuple->items = std::move(args);
  return arena_.make<GetitemExpr>(token.pos, node, tuple);
}

// subscribed := expression | [expression] ":" [expression] [":" [expression]]
Expr* Parser::parseSubscribed() {
  uint32_t pos = current().pos;
  Expr* parts[3] = {nullptr, nullptr, nullptr};
  if (current().is(Tok::Colon)) {
    next();
  } else {
    Expr* node = parseExpression();
    if (!current().is(Tok::Colon)) return node;
    next();
    parts[0] = node;
  }
  auto at_end = [&] { return current().is(Tok::RBracket) || current().is(Tok::Comma); };
  if (!current().is(Tok::Colon) && !at_end()) parts[1] = parseExpression();
  if (current().is(Tok::Colon)) {
    next();
    if (!at_end()) parts[2] = parseExpression();
  }
  return arena_.make<SliceExpr>(pos, parts[0], parts[1], parts[2]);
}

// call_args := "(" [arg ("," arg)* [","]] ")"
// arg := expression | NAME "=" expression | "*" expression | "**" expression
//   -- positional before keyword before *args before **kwargs
ArgList Parser::parseCallArgs() {
  NestingGuard guard(*this, current().pos);
  uint32_t pos = expect(Tok::LParen).pos;
  ArgList list;
  auto ensure = [&](bool ok) {
    if (!ok) failAt(pos, "invalid syntax for function call expression");
  };
  bool require_comma = false;
  while (!current().is(Tok::RParen)) {
    if (require_comma) {
      expect(Tok::Comma);
      if (current().is(Tok::RParen)) break;
    }
    if (skipIf(Tok::Mul)) {
      ensure(!list.dyn_args && !list.dyn_kwargs);
      list.dyn_args = parseExpression();
    } else if (skipIf(Tok::Pow)) {
      ensure(!list.dyn_kwargs);
      list.dyn_kwargs = parseExpression();
    } else if (current().is(Tok::Name) && peek().is(Tok::Assign)) {
      ensure(!list.dyn_kwargs);
      const std::string* key = name(textOf(next()));
      next();
      list.kwargs.emplace_back(key, parseExpression());
    } else {
      ensure(!list.dyn_args && !list.dyn_kwargs && list.kwargs.empty());
      list.args.push_back(parseExpression());
    }
    require_comma = true;
  }
  expect(Tok::RParen);
  return list;
}

// filter_chain := ("|" filter_name [call_args])+   (at a name: the first "|" left out)
// filter_name := NAME ("." NAME)*
FilterExpr* Parser::parseFilterChain(Expr* input, FilterStart start) {
  FilterExpr* node = nullptr;
  bool at_name = start == FilterStart::AtName;
  while (current().is(Tok::Pipe) || at_name) {
    if (!at_name) next();
    at_name = false;
    const Token& token = expect(Tok::Name);
    std::string filter_name(textOf(token));
    while (skipIf(Tok::Dot)) filter_name += "." + std::string(textOf(expect(Tok::Name)));
    node = arena_.make<FilterExpr>(token.pos, input, name(filter_name));
    node->def = registry_.filter(filter_name);
    if (!node->def) {
      failAt(token.pos, "unknown filter `" + filter_name + "`" +
                            didYouMean(filter_name, registry_.filterNames()));
    }
    if (current().is(Tok::LParen)) node->args = parseCallArgs();
    input = node;
  }
  return node;
}

// test := "is" ["not"] test_name [call_args | primary postfix*]
// test_name := NAME ("." NAME)*
Expr* Parser::parseTest(Expr* node) {
  uint32_t pos = next().pos;
  bool negated = skipName("not");
  const Token& token = expect(Tok::Name);
  std::string test_name(textOf(token));
  while (skipIf(Tok::Dot)) test_name += "." + std::string(textOf(expect(Tok::Name)));
  auto* test = arena_.make<TestExpr>(token.pos, node, name(test_name));
  test->def = registry_.test(test_name);
  if (!test->def) {
    failAt(token.pos,
           "unknown test `" + test_name + "`" + didYouMean(test_name, registry_.testNames()));
  }
  const Token& t = current();
  bool arg_start = t.is(Tok::Name) || t.is(Tok::String) || t.is(Tok::Integer) || t.is(Tok::Float) ||
                   t.is(Tok::LParen) || t.is(Tok::LBracket) || t.is(Tok::LBrace);
  if (t.is(Tok::LParen)) {
    test->args = parseCallArgs();
  } else if (arg_start && !isName(t, "else") && !isName(t, "or") && !isName(t, "and")) {
    if (isName(t, "is")) failAt(t.pos, "you cannot chain multiple tests with `is`");
    test->args.args.push_back(parsePostfix(parsePrimary()));
  }
  if (!negated) return test;
  return arena_.make<UnaryExpr>(ExprKind::Not, pos, test);
}

// target_name := NAME
NameExpr* Parser::parseTargetName() {
  return static_cast<NameExpr*>(parseAssignTarget({.with_tuple = false, .name_only = true}));
}

// assign_target := NAME "." NAME        (with_namespace)
//                | NAME                  (name_only)
//                | target_tuple | primary   -- whose names become stores
Expr* Parser::parseAssignTarget(const AssignTargetOptions& options) {
  Expr* target;
  if (options.with_namespace && peek().is(Tok::Dot)) {
    const Token& ns = expect(Tok::Name);
    next();
    const Token& attr = expect(Tok::Name);
    auto* ref = arena_.make<NameExpr>(ns.pos, name(textOf(ns)), NameCtx::Load);
    return arena_.make<NamespaceRefExpr>(attr.pos, ref, name(textOf(attr)));
  }
  if (options.name_only) {
    const Token& token = expect(Tok::Name);
    return arena_.make<NameExpr>(token.pos, name(textOf(token)), NameCtx::Store);
  }
  target = options.with_tuple ? parseTuple({.simplified = true, .extra_end = options.extra_end})
                              : parsePrimary();
  auto set_store = [&](auto&& self, Expr* e) -> void {
    if (e->kind == ExprKind::Name) {
      static_cast<NameExpr*>(e)->ctx = NameCtx::Store;
      return;
    }
    if (e->kind == ExprKind::Tuple) {
      for (Expr* item : static_cast<SeqExpr*>(e)->items) self(self, item);
      return;
    }
    failAt(e->pos, "cannot assign to this expression");
  };
  set_store(set_store, target);
  return target;
}

}  // namespace smachac::tmpl
