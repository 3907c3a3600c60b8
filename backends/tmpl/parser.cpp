// Statement parsing: data and `{{ }}` into text/print statements, and every `{% %}` tag of the
// supported Jinja2 subset (backends/tmpl/README.md), with Jinja's end-tag rules.
#include "backends/tmpl/parser.h"

#include <algorithm>

#include "backends/tmpl/error.h"

namespace smachac::tmpl {
namespace {

const std::vector<std::string_view> kKnownTags = {
    "for",    "if",  "block", "extends", "print",  "macro", "include", "from",
    "import", "set", "with",  "call",    "filter", "do",    "raw",
};

std::string joinQuoted(const std::vector<std::string_view>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += "`" + std::string(names[i]) + "`";
  }
  return out;
}

}  // namespace

ParsedTemplate parseTemplate(std::string_view source, const std::vector<Token>& tokens,
                             const Registry& registry, Arena& arena) {
  return Parser(source, tokens, registry, arena).parse();
}

ParsedTemplate Parser::parse() {
  result_.body = subparse({});
  return std::move(result_);
}

bool Parser::skipIf(Tok kind) {
  if (!current().is(kind)) return false;
  next();
  return true;
}

bool Parser::skipName(std::string_view text) {
  if (!current().isName(text)) return false;
  next();
  return true;
}

const Token& Parser::expect(Tok kind) {
  if (!current().is(kind)) {
    failAt(current().pos,
           "expected `" + std::string(describe(kind)) + "`, got " + shown(current()));
  }
  return next();
}

const Token& Parser::expectName(std::string_view text) {
  if (!current().isName(text)) {
    failAt(current().pos, "expected `" + std::string(text) + "`, got " + shown(current()));
  }
  return next();
}

void Parser::failAt(uint32_t pos, std::string message) const {
  throw SyntaxFault{pos, std::move(message)};
}

std::string Parser::shown(const Token& token) const {
  if (token.is(Tok::kEof)) return "end of template";
  if (token.is(Tok::kData)) return "template data";
  return "`" + std::string(token.text) + "`";
}

Body Parser::subparse(std::initializer_list<std::string_view> endTokens) {
  bool tracked = endTokens.size() > 0;
  if (tracked) endTokenStack_.emplace_back(endTokens);
  Body body;
  while (!current().is(Tok::kEof)) {
    const Token& token = current();
    if (token.is(Tok::kData)) {
      body.push_back(arena_.make<TextStmt>(token.pos, token.text));
      next();
    } else if (token.is(Tok::kVariableBegin)) {
      next();
      Expr* expr = parseTuple(false, true, {}, false);
      body.push_back(arena_.make<PrintStmt>(token.pos, expr));
      expect(Tok::kVariableEnd);
    } else {
      next();
      bool atEnd = std::any_of(endTokens.begin(), endTokens.end(),
                               [&](std::string_view name) { return current().isName(name); });
      if (atEnd) break;
      body.push_back(parseStatement());
      expect(Tok::kBlockEnd);
    }
  }
  if (tracked) endTokenStack_.pop_back();
  return body;
}

Body Parser::parseStatements(std::initializer_list<std::string_view> endTokens, bool dropNeedle) {
  skipIf(Tok::kColon);
  expect(Tok::kBlockEnd);
  Body body = subparse(endTokens);
  if (current().is(Tok::kEof)) {
    endTokenStack_.emplace_back(endTokens);
    failEof();
  }
  if (dropNeedle) next();
  return body;
}

Stmt* Parser::parseStatement() {
  const Token& token = current();
  if (!token.is(Tok::kName)) failAt(token.pos, "expected a tag name, got " + shown(token));
  NestingGuard guard(*this, token.pos);
  tagStack_.push_back({token.text, token.pos});
  Stmt* stmt = nullptr;
  std::string_view tag = token.text;
  if (tag == "for")
    stmt = parseFor();
  else if (tag == "if")
    stmt = parseIf();
  else if (tag == "block")
    stmt = parseBlock();
  else if (tag == "extends")
    stmt = parseExtends();
  else if (tag == "print")
    stmt = parsePrint();
  else if (tag == "macro")
    stmt = parseMacro();
  else if (tag == "include")
    stmt = parseInclude();
  else if (tag == "from")
    stmt = parseFrom();
  else if (tag == "import")
    stmt = parseImport();
  else if (tag == "set")
    stmt = parseSet();
  else if (tag == "with")
    stmt = parseWith();
  else if (tag == "call")
    stmt = parseCallBlock();
  else if (tag == "filter")
    stmt = parseFilterBlock();
  else if (tag == "do")
    stmt = parseDo();
  else if (tag == "autoescape")
    failAt(token.pos, "the `autoescape` tag is not supported");
  else
    failUnknownTag(token);
  tagStack_.pop_back();
  return stmt;
}

void Parser::failUnknownTag(const Token& token) {
  std::vector<std::string_view> expected;
  for (const auto& ends : endTokenStack_) expected.insert(expected.end(), ends.begin(), ends.end());
  bool nestingMistake = std::find(expected.begin(), expected.end(), token.text) != expected.end();
  if (nestingMistake && !endTokenStack_.empty()) {
    failAt(token.pos, "unexpected `" + std::string(token.text) + "`; expected " +
                          joinQuoted(endTokenStack_.back()) + " first");
  }
  std::string message = "unknown tag `" + std::string(token.text) + "`";
  std::vector<std::string_view> candidates = kKnownTags;
  if (!endTokenStack_.empty()) {
    candidates.insert(candidates.end(), endTokenStack_.back().begin(), endTokenStack_.back().end());
  }
  std::string suggestion = didYouMean(token.text, candidates);
  if (suggestion.empty() && !endTokenStack_.empty()) {
    suggestion = "; expected " + joinQuoted(endTokenStack_.back());
  }
  failAt(token.pos, message + suggestion);
}

void Parser::failEof() {
  std::string message = "unexpected end of template";
  if (!endTokenStack_.empty()) message += "; expected " + joinQuoted(endTokenStack_.back());
  if (!tagStack_.empty()) {
    uint32_t pos = tagStack_.back().pos;
    auto line = 1 + std::count(source_.begin(), source_.begin() + pos, '\n');
    message +=
        " to close `" + std::string(tagStack_.back().name) + "` from line " + std::to_string(line);
  }
  failAt(current().pos, message);
}

Stmt* Parser::parseFor() {
  auto* node = arena_.make<ForStmt>(expectName("for").pos);
  node->target = parseAssignTarget(true, false, {"in"}, false);
  expectName("in");
  node->iter = parseTuple(false, false, {"recursive"}, false);
  if (skipName("if")) node->filter = parseExpression();
  if (current().isName("recursive")) failAt(current().pos, "recursive loops are not supported");
  node->body = parseStatements({"endfor", "else"}, false);
  if (next().text != "endfor") node->orelse = parseStatements({"endfor"}, true);
  return node;
}

Stmt* Parser::parseIf() {
  auto* node = arena_.make<IfStmt>(expectName("if").pos);
  while (true) {
    Expr* test = parseTuple(false, false, {}, false);
    Body body = parseStatements({"elif", "else", "endif"}, false);
    node->branches.emplace_back(test, std::move(body));
    const Token& token = next();
    if (token.text == "elif") continue;
    if (token.text == "else") node->orelse = parseStatements({"endif"}, true);
    return node;
  }
}

Stmt* Parser::parseBlock() {
  auto* node = arena_.make<BlockStmt>(next().pos);
  const Token& nameToken = expect(Tok::kName);
  node->name = name(nameToken.text);
  for (const BlockStmt* other : result_.blocks) {
    if (other->name == node->name) {
      failAt(nameToken.pos, "block `" + *node->name + "` defined twice");
    }
  }
  node->scoped = skipName("scoped");
  node->required = skipName("required");
  if (current().is(Tok::kSub)) {
    failAt(current().pos, "block names must be identifiers; use `_` instead of `-`");
  }
  node->enclosing = blockStack_;
  if (result_.blocks.size() >= UINT16_MAX) failAt(node->pos, "too many blocks");
  node->index = static_cast<uint16_t>(result_.blocks.size());
  result_.blocks.push_back(node);
  blockStack_.push_back(node->name);
  node->body = parseStatements({"endblock"}, true);
  blockStack_.pop_back();
  if (node->required) {
    for (const Stmt* s : node->body) {
      auto* text = s->kind == StmtKind::kText ? static_cast<const TextStmt*>(s) : nullptr;
      if (!text || text->text.find_first_not_of(" \t\n\r\f\v") != std::string_view::npos) {
        failAt(node->pos, "required blocks can only contain comments or whitespace");
      }
    }
  }
  skipName(*node->name);
  return node;
}

// The template name of extends/include/import; string literals are noted as references.
Expr* Parser::parseTemplateName() {
  Expr* templateName = parseExpression();
  auto note = [&](const Expr* e) {
    if (e->kind != ExprKind::kConst) return;
    const Value& v = static_cast<const ConstExpr*>(e)->value;
    if (v.isString()) result_.references.emplace_back(v.s(), e->pos);
  };
  if (templateName->kind == ExprKind::kList || templateName->kind == ExprKind::kTuple) {
    for (const Expr* item : static_cast<const SeqExpr*>(templateName)->items) note(item);
  } else {
    note(templateName);
  }
  return templateName;
}

Stmt* Parser::parseExtends() {
  uint32_t pos = next().pos;
  auto* node = arena_.make<ExtendsStmt>(pos, parseTemplateName());
  result_.hasExtends = true;
  return node;
}

bool Parser::parseContextFlag(bool& withContext) {
  if ((current().isName("with") || current().isName("without")) && peek().isName("context")) {
    withContext = next().text == "with";
    next();
    return true;
  }
  return false;
}

Stmt* Parser::parseInclude() {
  auto* node = arena_.make<IncludeStmt>(next().pos);
  node->templateName = parseTemplateName();
  if (current().isName("ignore") && peek().isName("missing")) {
    next();
    next();
    node->ignoreMissing = true;
  }
  parseContextFlag(node->withContext);
  return node;
}

Stmt* Parser::parseImport() {
  auto* node = arena_.make<ImportStmt>(next().pos);
  node->templateName = parseTemplateName();
  expectName("as");
  node->target = static_cast<NameExpr*>(parseAssignTarget(false, true, {}, false));
  parseContextFlag(node->withContext);
  return node;
}

Stmt* Parser::parseFrom() {
  auto* node = arena_.make<FromImportStmt>(next().pos);
  node->templateName = parseTemplateName();
  expectName("import");
  while (true) {
    if (!node->names.empty()) expect(Tok::kComma);
    if (!current().is(Tok::kName)) {
      expect(Tok::kName);
    }
    if (parseContextFlag(node->withContext)) break;
    const Token& token = next();
    if (token.text.front() == '_') {
      failAt(token.pos, "names starting with an underscore cannot be imported");
    }
    NameExpr* alias;
    if (skipName("as")) {
      alias = static_cast<NameExpr*>(parseAssignTarget(false, true, {}, false));
    } else {
      alias = arena_.make<NameExpr>(token.pos, name(token.text), NameCtx::kStore);
    }
    node->names.push_back({name(token.text), alias});
    if (parseContextFlag(node->withContext) || !current().is(Tok::kComma)) break;
  }
  return node;
}

void Parser::parseSignature(MacroStmt* macro) {
  expect(Tok::kLParen);
  while (!current().is(Tok::kRParen)) {
    if (!macro->params.empty()) expect(Tok::kComma);
    auto* param = static_cast<NameExpr*>(parseAssignTarget(false, true, {}, false));
    param->ctx = NameCtx::kParam;
    if (skipIf(Tok::kAssign)) {
      macro->defaults.push_back(parseExpression());
    } else if (!macro->defaults.empty()) {
      failAt(param->pos, "non-default argument follows default argument");
    }
    macro->params.push_back(param);
  }
  expect(Tok::kRParen);
}

Stmt* Parser::parseMacro() {
  auto* node = arena_.make<MacroStmt>(StmtKind::kMacro, next().pos);
  node->target = static_cast<NameExpr*>(parseAssignTarget(false, true, {}, false));
  node->name = node->target->name;
  parseSignature(node);
  node->body = parseStatements({"endmacro"}, true);
  return node;
}

Stmt* Parser::parseCallBlock() {
  auto* node = arena_.make<CallBlockStmt>(next().pos);
  if (current().is(Tok::kLParen)) parseSignature(node);
  Expr* call = parseExpression();
  if (call->kind != ExprKind::kCall) failAt(call->pos, "expected a call after `call`");
  node->call = static_cast<CallExpr*>(call);
  node->body = parseStatements({"endcall"}, true);
  return node;
}

Stmt* Parser::parseFilterBlock() {
  auto* node = arena_.make<FilterBlockStmt>(next().pos);
  node->filter = parseFilterChain(nullptr, true);
  node->body = parseStatements({"endfilter"}, true);
  return node;
}

Stmt* Parser::parseSet() {
  uint32_t pos = next().pos;
  Expr* target = parseAssignTarget(true, false, {}, true);
  if (skipIf(Tok::kAssign)) {
    auto* node = arena_.make<SetStmt>(pos);
    node->target = target;
    node->value = parseTuple(false, true, {}, false);
    return node;
  }
  auto* node = arena_.make<SetBlockStmt>(pos);
  node->target = target;
  if (target->kind == ExprKind::kNamespaceRef)
    failAt(pos, "a block `set` cannot assign to a namespace");
  node->filter = parseFilterChain(nullptr, false);
  node->body = parseStatements({"endset"}, true);
  return node;
}

Stmt* Parser::parseWith() {
  auto* node = arena_.make<WithStmt>(next().pos);
  while (!current().is(Tok::kBlockEnd)) {
    if (!node->targets.empty()) expect(Tok::kComma);
    Expr* target = parseAssignTarget(true, false, {}, false);
    auto setParam = [](auto&& self, Expr* e) -> void {
      if (e->kind == ExprKind::kName) static_cast<NameExpr*>(e)->ctx = NameCtx::kParam;
      if (e->kind == ExprKind::kTuple) {
        for (Expr* item : static_cast<SeqExpr*>(e)->items) self(self, item);
      }
    };
    setParam(setParam, target);
    node->targets.push_back(target);
    expect(Tok::kAssign);
    node->values.push_back(parseExpression());
  }
  node->body = parseStatements({"endwith"}, true);
  return node;
}

Stmt* Parser::parseDo() {
  uint32_t pos = next().pos;
  Expr* expr = parseTuple(false, true, {}, false);
  return arena_.make<DoStmt>(pos, expr);
}

Stmt* Parser::parsePrint() {
  uint32_t pos = next().pos;
  auto* concat = arena_.make<ConcatExpr>(pos);
  while (!current().is(Tok::kBlockEnd)) {
    if (!concat->items.empty()) expect(Tok::kComma);
    concat->items.push_back(parseExpression());
  }
  if (concat->items.size() == 1) return arena_.make<PrintStmt>(pos, concat->items[0]);
  return arena_.make<PrintStmt>(pos, concat);
}

}  // namespace smachac::tmpl
