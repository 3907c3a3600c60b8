// Expression parsing (Jinja2 precedence, lowest first): conditional `a if c else b`, `or`,
// `and`, `not`, comparisons and `in`, `+ -`, `~`, `* / // %`, `**` (left-associative), unary
// `- +`, then primaries with postfix `.attr`, `[index]`, calls, `|filter` and `is test`.
#include <charconv>
#include <cmath>

#include "backends/tmpl/error.h"
#include "backends/tmpl/parser.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

constexpr int kMaxNesting = 100;

bool isCompareToken(Tok kind, CmpOp& op) {
  static constexpr std::pair<Tok, CmpOp> kOps[] = {
      {Tok::kEq, CmpOp::kEq}, {Tok::kNe, CmpOp::kNe}, {Tok::kLt, CmpOp::kLt},
      {Tok::kLe, CmpOp::kLe}, {Tok::kGt, CmpOp::kGt}, {Tok::kGe, CmpOp::kGe},
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
  if (++parser_.nesting_ > kMaxNesting) {
    --parser_.nesting_;
    parser_.failAt(pos, "template nested too deeply (limit " + std::to_string(kMaxNesting) + ")");
  }
}

Expr* Parser::parseExpression(bool withCondExpr) {
  NestingGuard guard(*this, current().pos);
  return withCondExpr ? parseCondExpr() : parseOr();
}

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
  while (current().isName(word)) {
    uint32_t pos = next().pos;
    left = arena_.make<BinaryExpr>(kind, pos, BinOp::kAdd, left, (this->*operand)());
  }
  return left;
}

Expr* Parser::parseOr() { return parseLogic(ExprKind::kOr, "or", &Parser::parseAnd); }

Expr* Parser::parseAnd() { return parseLogic(ExprKind::kAnd, "and", &Parser::parseNot); }

Expr* Parser::parseNot() {
  if (current().isName("not")) {
    NestingGuard guard(*this, current().pos);
    uint32_t pos = next().pos;
    return arena_.make<UnaryExpr>(ExprKind::kNot, pos, parseNot());
  }
  return parseCompare();
}

Expr* Parser::parseCompare() {
  Expr* expr = parseMath1();
  CompareExpr* compare = nullptr;
  while (true) {
    CmpOp op;
    uint32_t pos = current().pos;
    if (isCompareToken(current().kind, op)) {
      next();
    } else if (skipName("in")) {
      op = CmpOp::kIn;
    } else if (current().isName("not") && peek().isName("in")) {
      next();
      next();
      op = CmpOp::kNotIn;
    } else {
      break;
    }
    if (!compare) compare = arena_.make<CompareExpr>(pos, expr);
    compare->ops.emplace_back(op, parseMath1());
  }
  return compare ? compare : expr;
}

Expr* Parser::parseMath1() {
  Expr* left = parseConcat();
  while (current().is(Tok::kAdd) || current().is(Tok::kSub)) {
    BinOp op = current().is(Tok::kAdd) ? BinOp::kAdd : BinOp::kSub;
    uint32_t pos = next().pos;
    left = arena_.make<BinaryExpr>(ExprKind::kBinary, pos, op, left, parseConcat());
  }
  return left;
}

Expr* Parser::parseConcat() {
  Expr* first = parseMath2();
  if (!current().is(Tok::kTilde)) return first;
  auto* concat = arena_.make<ConcatExpr>(current().pos);
  concat->items.push_back(first);
  while (skipIf(Tok::kTilde)) concat->items.push_back(parseMath2());
  return concat;
}

Expr* Parser::parseMath2() {
  Expr* left = parsePow();
  while (true) {
    BinOp op;
    switch (current().kind) {
      case Tok::kMul:
        op = BinOp::kMul;
        break;
      case Tok::kDiv:
        op = BinOp::kDiv;
        break;
      case Tok::kFloorDiv:
        op = BinOp::kFloorDiv;
        break;
      case Tok::kMod:
        op = BinOp::kMod;
        break;
      default:
        return left;
    }
    uint32_t pos = next().pos;
    left = arena_.make<BinaryExpr>(ExprKind::kBinary, pos, op, left, parsePow());
  }
}

Expr* Parser::parsePow() {
  Expr* left = parseUnary(true);
  while (current().is(Tok::kPow)) {
    uint32_t pos = next().pos;
    left = arena_.make<BinaryExpr>(ExprKind::kBinary, pos, BinOp::kPow, left, parseUnary(true));
  }
  return left;
}

Expr* Parser::parseUnary(bool withFilter) {
  NestingGuard guard(*this, current().pos);
  Expr* node;
  if (current().is(Tok::kSub) || current().is(Tok::kAdd)) {
    ExprKind kind = current().is(Tok::kSub) ? ExprKind::kNeg : ExprKind::kPos;
    uint32_t pos = next().pos;
    node = arena_.make<UnaryExpr>(kind, pos, parseUnary(false));
  } else {
    node = parsePrimary();
  }
  node = parsePostfix(node);
  return withFilter ? parseFilterExpr(node) : node;
}

Expr* Parser::parsePrimary() {
  const Token& token = current();
  switch (token.kind) {
    case Tok::kName: {
      next();
      if (token.text == "true" || token.text == "True") {
        return arena_.make<ConstExpr>(token.pos, Value::boolean(true));
      }
      if (token.text == "false" || token.text == "False") {
        return arena_.make<ConstExpr>(token.pos, Value::boolean(false));
      }
      if (token.text == "none" || token.text == "None") {
        return arena_.make<ConstExpr>(token.pos, Value::none());
      }
      return arena_.make<NameExpr>(token.pos, name(token.text), NameCtx::kLoad);
    }
    case Tok::kString:
      return parseStringLiteral();
    case Tok::kInteger:
    case Tok::kFloat:
      return parseNumber(next());
    case Tok::kLParen: {
      NestingGuard guard(*this, token.pos);
      next();
      Expr* node = parseTuple(false, true, {}, true);
      expect(Tok::kRParen);
      return node;
    }
    case Tok::kLBracket:
      return parseList();
    case Tok::kLBrace:
      return parseDict();
    default:
      failAt(token.pos, "unexpected " + shown(token));
  }
}

Expr* Parser::parseStringLiteral() {
  uint32_t pos = current().pos;
  std::string text;
  while (current().is(Tok::kString)) {
    const Token& token = next();
    text += unescapeString(token.text.substr(1, token.text.size() - 2), token.pos);
  }
  return arena_.make<ConstExpr>(pos, Value::string(std::move(text)));
}

Expr* Parser::parseNumber(const Token& token) {
  std::string digits;
  for (char c : token.text) {
    if (c != '_') digits.push_back(c);
  }
  if (token.is(Tok::kFloat)) {
    double d = 0;
    auto result = std::from_chars(digits.data(), digits.data() + digits.size(), d);
    if (result.ec == std::errc::result_out_of_range) {
      size_t e = digits.find_first_of("eE");
      bool negativeExponent = e != std::string::npos && digits[e + 1] == '-';
      d = negativeExponent ? 0.0 : HUGE_VAL;
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

bool Parser::isTupleEnd(std::initializer_list<std::string_view> extraEnd) const {
  const Token& t = current();
  if (t.is(Tok::kVariableEnd) || t.is(Tok::kBlockEnd) || t.is(Tok::kRParen)) return true;
  for (std::string_view name : extraEnd) {
    if (t.isName(name)) return true;
  }
  return false;
}

Expr* Parser::parseTuple(bool simplified, bool withCondExpr,
                         std::initializer_list<std::string_view> extraEnd, bool explicitParens) {
  uint32_t pos = current().pos;
  std::vector<Expr*> items;
  bool isTuple = false;
  while (true) {
    if (!items.empty()) expect(Tok::kComma);
    if (isTupleEnd(extraEnd)) break;
    items.push_back(simplified ? parsePrimary() : parseExpression(withCondExpr));
    if (!current().is(Tok::kComma)) break;
    isTuple = true;
  }
  if (!isTuple) {
    if (!items.empty()) return items[0];
    if (!explicitParens) failAt(current().pos, "expected an expression, got " + shown(current()));
  }
  auto* tuple = arena_.make<SeqExpr>(ExprKind::kTuple, pos);
  tuple->items = std::move(items);
  return tuple;
}

Expr* Parser::parseList() {
  NestingGuard guard(*this, current().pos);
  auto* list = arena_.make<SeqExpr>(ExprKind::kList, expect(Tok::kLBracket).pos);
  while (!current().is(Tok::kRBracket)) {
    if (!list->items.empty()) expect(Tok::kComma);
    if (current().is(Tok::kRBracket)) break;
    list->items.push_back(parseExpression());
  }
  expect(Tok::kRBracket);
  return list;
}

Expr* Parser::parseDict() {
  NestingGuard guard(*this, current().pos);
  auto* dict = arena_.make<DictExpr>(expect(Tok::kLBrace).pos);
  while (!current().is(Tok::kRBrace)) {
    if (!dict->items.empty()) expect(Tok::kComma);
    if (current().is(Tok::kRBrace)) break;
    Expr* key = parseExpression();
    expect(Tok::kColon);
    dict->items.emplace_back(key, parseExpression());
  }
  expect(Tok::kRBrace);
  return dict;
}

Expr* Parser::parseCall(Expr* callee) {
  auto* call = arena_.make<CallExpr>(callee->pos, callee);
  call->args = parseCallArgs();
  return call;
}

Expr* Parser::parsePostfix(Expr* node) {
  while (true) {
    if (current().is(Tok::kDot) || current().is(Tok::kLBracket)) {
      node = parseSubscript(node);
    } else if (current().is(Tok::kLParen)) {
      node = parseCall(node);
    } else {
      return node;
    }
  }
}

Expr* Parser::parseFilterExpr(Expr* node) {
  while (true) {
    if (current().is(Tok::kPipe)) {
      node = parseFilterChain(node, false);
    } else if (current().isName("is")) {
      node = parseTest(node);
    } else if (current().is(Tok::kLParen)) {
      node = parseCall(node);
    } else {
      return node;
    }
  }
}

Expr* Parser::parseSubscript(Expr* node) {
  NestingGuard guard(*this, current().pos);
  const Token& token = next();
  if (token.is(Tok::kDot)) {
    const Token& attr = next();
    if (attr.is(Tok::kName)) return arena_.make<GetattrExpr>(attr.pos, node, name(attr.text));
    if (!attr.is(Tok::kInteger)) failAt(attr.pos, "expected name or number after `.`");
    return arena_.make<GetitemExpr>(attr.pos, node, parseNumber(attr));
  }
  std::vector<Expr*> args;
  while (!current().is(Tok::kRBracket)) {
    if (!args.empty()) expect(Tok::kComma);
    args.push_back(parseSubscribed());
  }
  expect(Tok::kRBracket);
  if (args.size() == 1) return arena_.make<GetitemExpr>(token.pos, node, args[0]);
  auto* tuple = arena_.make<SeqExpr>(ExprKind::kTuple, token.pos);
  tuple->items = std::move(args);
  return arena_.make<GetitemExpr>(token.pos, node, tuple);
}

Expr* Parser::parseSubscribed() {
  uint32_t pos = current().pos;
  Expr* parts[3] = {nullptr, nullptr, nullptr};
  if (current().is(Tok::kColon)) {
    next();
  } else {
    Expr* node = parseExpression();
    if (!current().is(Tok::kColon)) return node;
    next();
    parts[0] = node;
  }
  auto atEnd = [&] { return current().is(Tok::kRBracket) || current().is(Tok::kComma); };
  if (!current().is(Tok::kColon) && !atEnd()) parts[1] = parseExpression();
  if (current().is(Tok::kColon)) {
    next();
    if (!atEnd()) parts[2] = parseExpression();
  }
  return arena_.make<SliceExpr>(pos, parts[0], parts[1], parts[2]);
}

ArgList Parser::parseCallArgs() {
  NestingGuard guard(*this, current().pos);
  uint32_t pos = expect(Tok::kLParen).pos;
  ArgList list;
  auto ensure = [&](bool ok) {
    if (!ok) failAt(pos, "invalid syntax for function call expression");
  };
  bool requireComma = false;
  while (!current().is(Tok::kRParen)) {
    if (requireComma) {
      expect(Tok::kComma);
      if (current().is(Tok::kRParen)) break;
    }
    if (skipIf(Tok::kMul)) {
      ensure(!list.dynArgs && !list.dynKwargs);
      list.dynArgs = parseExpression();
    } else if (skipIf(Tok::kPow)) {
      ensure(!list.dynKwargs);
      list.dynKwargs = parseExpression();
    } else if (current().is(Tok::kName) && peek().is(Tok::kAssign)) {
      ensure(!list.dynKwargs);
      const std::string* key = name(next().text);
      next();
      list.kwargs.emplace_back(key, parseExpression());
    } else {
      ensure(!list.dynArgs && !list.dynKwargs && list.kwargs.empty());
      list.args.push_back(parseExpression());
    }
    requireComma = true;
  }
  expect(Tok::kRParen);
  return list;
}

FilterExpr* Parser::parseFilterChain(Expr* input, bool startInline) {
  FilterExpr* node = nullptr;
  while (current().is(Tok::kPipe) || startInline) {
    if (!startInline) next();
    startInline = false;
    const Token& token = expect(Tok::kName);
    std::string filterName(token.text);
    while (skipIf(Tok::kDot)) filterName += "." + std::string(expect(Tok::kName).text);
    node = arena_.make<FilterExpr>(token.pos, input, name(filterName));
    node->def = registry_.filter(filterName);
    if (!node->def) {
      failAt(token.pos, "unknown filter `" + filterName + "`" +
                            didYouMean(filterName, registry_.filterNames()));
    }
    if (current().is(Tok::kLParen)) node->args = parseCallArgs();
    input = node;
  }
  return node;
}

Expr* Parser::parseTest(Expr* node) {
  uint32_t pos = next().pos;
  bool negated = skipName("not");
  const Token& token = expect(Tok::kName);
  std::string testName(token.text);
  while (skipIf(Tok::kDot)) testName += "." + std::string(expect(Tok::kName).text);
  auto* test = arena_.make<TestExpr>(token.pos, node, name(testName));
  test->def = registry_.test(testName);
  if (!test->def) {
    failAt(token.pos,
           "unknown test `" + testName + "`" + didYouMean(testName, registry_.testNames()));
  }
  const Token& t = current();
  bool argStart = t.is(Tok::kName) || t.is(Tok::kString) || t.is(Tok::kInteger) ||
                  t.is(Tok::kFloat) || t.is(Tok::kLParen) || t.is(Tok::kLBracket) ||
                  t.is(Tok::kLBrace);
  if (t.is(Tok::kLParen)) {
    test->args = parseCallArgs();
  } else if (argStart && !t.isName("else") && !t.isName("or") && !t.isName("and")) {
    if (t.isName("is")) failAt(t.pos, "you cannot chain multiple tests with `is`");
    test->args.args.push_back(parsePostfix(parsePrimary()));
  }
  if (!negated) return test;
  return arena_.make<UnaryExpr>(ExprKind::kNot, pos, test);
}

Expr* Parser::parseAssignTarget(bool withTuple, bool nameOnly,
                                std::initializer_list<std::string_view> extraEnd,
                                bool withNamespace) {
  Expr* target;
  if (withNamespace && peek().is(Tok::kDot)) {
    const Token& ns = expect(Tok::kName);
    next();
    const Token& attr = expect(Tok::kName);
    auto* ref = arena_.make<NameExpr>(ns.pos, name(ns.text), NameCtx::kLoad);
    return arena_.make<NamespaceRefExpr>(attr.pos, ref, name(attr.text));
  }
  if (nameOnly) {
    const Token& token = expect(Tok::kName);
    return arena_.make<NameExpr>(token.pos, name(token.text), NameCtx::kStore);
  }
  target = withTuple ? parseTuple(true, true, extraEnd, false) : parsePrimary();
  auto setStore = [&](auto&& self, Expr* e) -> void {
    if (e->kind == ExprKind::kName) {
      static_cast<NameExpr*>(e)->ctx = NameCtx::kStore;
      return;
    }
    if (e->kind == ExprKind::kTuple) {
      for (Expr* item : static_cast<SeqExpr*>(e)->items) self(self, item);
      return;
    }
    failAt(e->pos, "cannot assign to this expression");
  };
  setStore(setStore, target);
  return target;
}

}  // namespace smachac::tmpl
