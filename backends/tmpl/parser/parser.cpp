// Statement parsing: data and `{{ }}` into text/print statements, and every `{% %}` tag of the
// supported Jinja2 subset (backends/tmpl/README.md), with Jinja's end-tag rules.
#include "backends/tmpl/parser/parser.h"

#include <algorithm>

#include "backends/tmpl/error.h"

namespace smachac::tmpl {
namespace {

const std::vector<std::string_view> kKnownTags = {
    "for",    "if",  "block", "extends", "print",  "macro", "include", "from",
    "import", "set", "with",  "call",    "filter", "do",    "raw",
};

std::string joinQuoted(std::span<const std::string_view> names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += "`" + std::string(names[i]) + "`";
  }
  return out;
}

}  // namespace

ParsedTemplate parseTemplate(std::string_view source, std::span<const Token> tokens,
                             const Registry& registry, Arena& arena, bool defer_macros) {
  return Parser(source, tokens, registry, arena, defer_macros).parse();
}

// template := body
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
  if (!isName(current(), text)) return false;
  next();
  return true;
}

// The errors are built out of line, so that the checks that pass (nearly all) do not pay for
// the frame that building a message needs.
const Token& Parser::expect(Tok kind) {
  if (!current().is(kind)) [[unlikely]]
    failExpected(describe(kind));
  return next();
}

const Token& Parser::expectName(std::string_view text) {
  if (!isName(current(), text)) [[unlikely]]
    failExpected(text);
  return next();
}

void Parser::failExpected(std::string_view expected) const {
  failAt(current().pos, "expected `" + std::string(expected) + "`, got " + shown(current()));
}

void Parser::failGot(const Token& token, std::string_view prefix) const {
  failAt(token.pos, std::string(prefix) + shown(token));
}

void Parser::failAt(uint32_t pos, std::string message) const {
  throw SyntaxFault{pos, std::move(message)};
}

std::string Parser::shown(const Token& token) const {
  if (token.is(Tok::Eof)) return "end of template";
  if (token.is(Tok::Data)) return "template data";
  return "`" + std::string(textOf(token)) + "`";
}

// body := ( DATA | "{{" tuple "}}" | "{%" statement "%}" )*   -- up to one of `end_tokens`
Body Parser::subparse(std::initializer_list<std::string_view> end_tokens) {
  bool tracked = end_tokens.size() > 0;
  if (tracked) end_token_stack_.emplace_back(end_tokens.begin(), end_tokens.size());
  // The statements go to the shared scratch list (nested bodies after them) and the body is
  // made from them once, at its size, instead of growing a vector of its own.
  const size_t first = body_scratch_.size();
  while (!current().is(Tok::Eof)) {
    const Token& token = current();
    if (token.is(Tok::Data)) {
      body_scratch_.push_back(arena_.make<TextStmt>(token.pos, textOf(token)));
      next();
    } else if (token.is(Tok::VariableBegin)) {
      next();
      Expr* expr = parseTuple({});
      body_scratch_.push_back(arena_.make<PrintStmt>(token.pos, expr));
      expect(Tok::VariableEnd);
    } else {
      next();
      bool at_end = std::any_of(end_tokens.begin(), end_tokens.end(),
                                [&](std::string_view name) { return isName(current(), name); });
      if (at_end) break;
      Stmt* statement = parseStatement();
      body_scratch_.push_back(statement);
      expect(Tok::BlockEnd);
    }
  }
  if (tracked) end_token_stack_.pop_back();
  Body body(body_scratch_.begin() + static_cast<std::ptrdiff_t>(first), body_scratch_.end());
  body_scratch_.resize(first);
  return body;
}

// block_body := [":"] "%}" body   -- then the end tag (consumed or not, see EndTag)
Body Parser::parseStatements(std::initializer_list<std::string_view> end_tokens, EndTag end_tag) {
  skipIf(Tok::Colon);
  expect(Tok::BlockEnd);
  Body body = subparse(end_tokens);
  if (current().is(Tok::Eof)) {
    end_token_stack_.emplace_back(end_tokens.begin(), end_tokens.size());
    failEof();
  }
  if (end_tag == EndTag::Consume) next();
  return body;
}

// statement := for | if | block | extends | print | macro | include | from | import
//            | set | with | call | filter | do
Stmt* Parser::parseStatement() {
  const Token& token = current();
  if (!token.is(Tok::Name)) [[unlikely]]
    failGot(token, "expected a tag name, got ");
  NestingGuard guard(*this, token.pos);
  tag_stack_.push_back({textOf(token), token.pos});
  Stmt* stmt = nullptr;
  std::string_view tag = textOf(token);
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
  tag_stack_.pop_back();
  return stmt;
}

void Parser::failUnknownTag(const Token& token) {
  std::vector<std::string_view> expected;
  for (const auto& ends : end_token_stack_)
    expected.insert(expected.end(), ends.begin(), ends.end());
  bool nesting_mistake =
      std::find(expected.begin(), expected.end(), textOf(token)) != expected.end();
  if (nesting_mistake && !end_token_stack_.empty()) {
    failAt(token.pos, "unexpected `" + std::string(textOf(token)) + "`; expected " +
                          joinQuoted(end_token_stack_.back()) + " first");
  }
  std::string message = "unknown tag `" + std::string(textOf(token)) + "`";
  std::vector<std::string_view> candidates = kKnownTags;
  if (!end_token_stack_.empty()) {
    candidates.insert(candidates.end(), end_token_stack_.back().begin(),
                      end_token_stack_.back().end());
  }
  std::string suggestion = didYouMean(textOf(token), candidates);
  if (suggestion.empty() && !end_token_stack_.empty()) {
    suggestion = "; expected " + joinQuoted(end_token_stack_.back());
  }
  failAt(token.pos, message + suggestion);
}

void Parser::failEof() {
  std::string message = "unexpected end of template";
  if (!end_token_stack_.empty()) message += "; expected " + joinQuoted(end_token_stack_.back());
  if (!tag_stack_.empty()) {
    uint32_t pos = tag_stack_.back().pos;
    auto line = 1 + std::count(source_.begin(), source_.begin() + pos, '\n');
    message +=
        " to close `" + std::string(tag_stack_.back().name) + "` from line " + std::to_string(line);
  }
  failAt(current().pos, message);
}

// for := "for" assign_target "in" tuple_no_cond ["if" expression] block_body
//        ["else" block_body] "endfor"
Stmt* Parser::parseFor() {
  auto* node = arena_.make<ForStmt>(expectName("for").pos);
  node->target = parseAssignTarget({.extra_end = {"in"}});
  expectName("in");
  node->iter = parseTuple({.with_cond_expr = false, .extra_end = {"recursive"}});
  if (skipName("if")) node->filter = parseExpression();
  if (isName(current(), "recursive")) failAt(current().pos, "recursive loops are not supported");
  node->body = parseStatements({"endfor", "else"}, EndTag::Keep);
  if (textOf(next()) != "endfor") node->orelse = parseStatements({"endfor"}, EndTag::Consume);
  return node;
}

// if := "if" tuple_no_cond block_body ("elif" tuple_no_cond block_body)* ["else" block_body]
//       "endif"
Stmt* Parser::parseIf() {
  auto* node = arena_.make<IfStmt>(expectName("if").pos);
  while (true) {
    Expr* test = parseTuple({.with_cond_expr = false});
    Body body = parseStatements({"elif", "else", "endif"}, EndTag::Keep);
    node->branches.emplace_back(test, std::move(body));
    const Token& token = next();
    if (textOf(token) == "elif") continue;
    if (textOf(token) == "else") node->orelse = parseStatements({"endif"}, EndTag::Consume);
    return node;
  }
}

// block := "block" NAME ["scoped"] ["required"] block_body "endblock" [NAME]
Stmt* Parser::parseBlock() {
  auto* node = arena_.make<BlockStmt>(next().pos);
  const Token& name_token = expect(Tok::Name);
  node->name = name(textOf(name_token));
  for (const BlockStmt* other : result_.blocks) {
    if (other->name == node->name) {
      failAt(name_token.pos, "block `" + *node->name + "` defined twice");
    }
  }
  node->scoped = skipName("scoped");
  node->required = skipName("required");
  if (current().is(Tok::Sub)) {
    failAt(current().pos, "block names must be identifiers; use `_` instead of `-`");
  }
  node->enclosing = block_stack_;
  if (result_.blocks.size() >= UINT16_MAX) failAt(node->pos, "too many blocks");
  node->index = static_cast<uint16_t>(result_.blocks.size());
  result_.blocks.push_back(node);
  block_stack_.push_back(node->name);
  node->body = parseStatements({"endblock"}, EndTag::Consume);
  block_stack_.pop_back();
  if (node->required) {
    for (const Stmt* s : node->body) {
      auto* text = s->kind == StmtKind::Text ? static_cast<const TextStmt*>(s) : nullptr;
      if (!text || text->text.find_first_not_of(" \t\n\r\f\v") != std::string_view::npos) {
        failAt(node->pos, "required blocks can only contain comments or whitespace");
      }
    }
  }
  skipName(*node->name);
  return node;
}

// template_name := expression
// The template name of extends/include/import; string literals are noted as references.
Expr* Parser::parseTemplateName() {
  Expr* template_name = parseExpression();
  result_.names_templates = true;
  auto note = [&](const Expr* e) {
    if (e->kind != ExprKind::Const) return;
    const Value& v = static_cast<const ConstExpr*>(e)->value;
    if (v.isString()) result_.references.emplace_back(v.s(), e->pos);
  };
  if (template_name->kind == ExprKind::List || template_name->kind == ExprKind::Tuple) {
    for (const Expr* item : static_cast<const SeqExpr*>(template_name)->items) note(item);
  } else {
    note(template_name);
  }
  return template_name;
}

// extends := "extends" template_name
Stmt* Parser::parseExtends() {
  uint32_t pos = next().pos;
  auto* node = arena_.make<ExtendsStmt>(pos, parseTemplateName());
  result_.has_extends = true;
  return node;
}

// context_flag := ("with" | "without") "context"
bool Parser::parseContextFlag(bool& with_context) {
  if ((isName(current(), "with") || isName(current(), "without")) && isName(peek(), "context")) {
    with_context = textOf(next()) == "with";
    next();
    return true;
  }
  return false;
}

// include := "include" template_name ["ignore" "missing"] [context_flag]
Stmt* Parser::parseInclude() {
  auto* node = arena_.make<IncludeStmt>(next().pos);
  node->template_name = parseTemplateName();
  if (isName(current(), "ignore") && isName(peek(), "missing")) {
    next();
    next();
    node->ignore_missing = true;
  }
  parseContextFlag(node->with_context);
  return node;
}

// import := "import" template_name "as" target_name [context_flag]
Stmt* Parser::parseImport() {
  auto* node = arena_.make<ImportStmt>(next().pos);
  node->template_name = parseTemplateName();
  expectName("as");
  node->target = parseTargetName();
  parseContextFlag(node->with_context);
  return node;
}

// from := "from" template_name "import" imported ("," imported)* [","] [context_flag]
// imported := NAME ["as" target_name]
Stmt* Parser::parseFrom() {
  auto* node = arena_.make<FromImportStmt>(next().pos);
  node->template_name = parseTemplateName();
  expectName("import");
  while (true) {
    if (!node->names.empty()) expect(Tok::Comma);
    if (!current().is(Tok::Name)) {
      expect(Tok::Name);
    }
    if (parseContextFlag(node->with_context)) break;
    const Token& token = next();
    if (textOf(token).front() == '_') {
      failAt(token.pos, "names starting with an underscore cannot be imported");
    }
    NameExpr* alias;
    if (skipName("as")) {
      alias = parseTargetName();
    } else {
      alias = arena_.make<NameExpr>(token.pos, name(textOf(token)), NameCtx::Store);
    }
    node->names.push_back({name(textOf(token)), alias});
    if (parseContextFlag(node->with_context) || !current().is(Tok::Comma)) break;
  }
  return node;
}

// signature := "(" [param ("," param)*] ")"
// param := target_name ["=" expression]
void Parser::parseSignature(MacroStmt* macro) {
  expect(Tok::LParen);
  while (!current().is(Tok::RParen)) {
    if (!macro->params.empty()) expect(Tok::Comma);
    auto* param = parseTargetName();
    param->ctx = NameCtx::Param;
    if (skipIf(Tok::Assign)) {
      macro->defaults.push_back(parseExpression());
    } else if (!macro->defaults.empty()) {
      failAt(param->pos, "non-default argument follows default argument");
    }
    macro->params.push_back(param);
  }
  expect(Tok::RParen);
}

// macro := "macro" target_name signature block_body "endmacro"
Stmt* Parser::parseMacro() {
  auto* node = arena_.make<MacroStmt>(StmtKind::Macro, next().pos);
  node->target = parseTargetName();
  node->name = node->target->name;
  if (deferMacro(node)) return node;
  parseSignature(node);
  node->body = parseStatements({"endmacro"}, EndTag::Consume);
  return node;
}

// call := "call" [signature] expression block_body "endcall"   -- the expression a call
Stmt* Parser::parseCallBlock() {
  auto* node = arena_.make<CallBlockStmt>(next().pos);
  if (current().is(Tok::LParen)) parseSignature(node);
  Expr* call = parseExpression();
  if (call->kind != ExprKind::Call) failAt(call->pos, "expected a call after `call`");
  node->call = static_cast<CallExpr*>(call);
  node->body = parseStatements({"endcall"}, EndTag::Consume);
  return node;
}

// filter := "filter" filter_chain block_body "endfilter"   -- the chain starts at a name
Stmt* Parser::parseFilterBlock() {
  auto* node = arena_.make<FilterBlockStmt>(next().pos);
  node->filter = parseFilterChain(nullptr, FilterStart::AtName);
  node->body = parseStatements({"endfilter"}, EndTag::Consume);
  return node;
}

// set := "set" assign_target "=" tuple
//      | "set" assign_target filter_chain? block_body "endset"
Stmt* Parser::parseSet() {
  uint32_t pos = next().pos;
  Expr* target = parseAssignTarget({.with_namespace = true});
  if (skipIf(Tok::Assign)) {
    auto* node = arena_.make<SetStmt>(pos);
    node->target = target;
    node->value = parseTuple({});
    return node;
  }
  auto* node = arena_.make<SetBlockStmt>(pos);
  node->target = target;
  if (target->kind == ExprKind::NamespaceRef)
    failAt(pos, "a block `set` cannot assign to a namespace");
  node->filter = parseFilterChain(nullptr, FilterStart::AtPipe);
  node->body = parseStatements({"endset"}, EndTag::Consume);
  return node;
}

// with := "with" [assign_target "=" expression ("," assign_target "=" expression)*]
//         block_body "endwith"
Stmt* Parser::parseWith() {
  auto* node = arena_.make<WithStmt>(next().pos);
  while (!current().is(Tok::BlockEnd)) {
    if (!node->targets.empty()) expect(Tok::Comma);
    Expr* target = parseAssignTarget({});
    auto set_param = [](auto&& self, Expr* e) -> void {
      if (e->kind == ExprKind::Name) static_cast<NameExpr*>(e)->ctx = NameCtx::Param;
      if (e->kind == ExprKind::Tuple) {
        for (Expr* item : static_cast<SeqExpr*>(e)->items) self(self, item);
      }
    };
    set_param(set_param, target);
    node->targets.push_back(target);
    expect(Tok::Assign);
    node->values.push_back(parseExpression());
  }
  node->body = parseStatements({"endwith"}, EndTag::Consume);
  return node;
}

// do := "do" tuple
Stmt* Parser::parseDo() {
  uint32_t pos = next().pos;
  Expr* expr = parseTuple({});
  return arena_.make<DoStmt>(pos, expr);
}

// print := "print" [expression ("," expression)*]
Stmt* Parser::parsePrint() {
  uint32_t pos = next().pos;
  auto* concat = arena_.make<ConcatExpr>(pos);
  while (!current().is(Tok::BlockEnd)) {
    if (!concat->items.empty()) expect(Tok::Comma);
    concat->items.push_back(parseExpression());
  }
  if (concat->items.size() == 1) return arena_.make<PrintStmt>(pos, concat->items[0]);
  return arena_.make<PrintStmt>(pos, concat);
}

}  // namespace smachac::tmpl
