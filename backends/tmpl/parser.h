// The parser: turns the token stream of one template into statements and expressions with
// Jinja2's grammar and precedence. Filters and tests are resolved against the registry here,
// so an unknown one is a syntax error with its location.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "backends/tmpl/ast.h"
#include "backends/tmpl/builtins.h"
#include "backends/tmpl/lexer.h"

namespace smachac::tmpl {

/// What parsing one template produces.
struct ParsedTemplate {
  Body body;
  std::vector<BlockStmt*> blocks;                            // every block, in document order
  std::vector<std::pair<std::string, uint32_t>> references;  // literal names of extends etc.
  bool hasExtends = false;
};

/// Parses `tokens` (of `source`); raises SyntaxFault.
ParsedTemplate parseTemplate(std::string_view source, const std::vector<Token>& tokens,
                             const Registry& registry, Arena& arena);

class Parser {
 public:
  Parser(std::string_view source, const std::vector<Token>& tokens, const Registry& registry,
         Arena& arena)
      : source_(source), tokens_(tokens), registry_(registry), arena_(arena) {}

  ParsedTemplate parse();

  // Expressions (parser_expr.cpp).
  Expr* parseExpression(bool withCondExpr = true);
  Expr* parseTuple(bool simplified, bool withCondExpr,
                   std::initializer_list<std::string_view> extraEnd, bool explicitParens);
  Expr* parseAssignTarget(bool withTuple, bool nameOnly,
                          std::initializer_list<std::string_view> extraEnd, bool withNamespace);
  FilterExpr* parseFilterChain(Expr* input, bool startInline);
  ArgList parseCallArgs();

 private:
  // Token stream.
  const Token& current() const { return tokens_[index_]; }
  const Token& peek() const { return tokens_[index_ + 1 < tokens_.size() ? index_ + 1 : index_]; }
  const Token& next() { return tokens_[index_ < tokens_.size() - 1 ? index_++ : index_]; }
  bool skipIf(Tok kind);
  bool skipName(std::string_view name);
  const Token& expect(Tok kind);
  const Token& expectName(std::string_view name);
  [[noreturn]] void failAt(uint32_t pos, std::string message) const;
  [[noreturn]] void failUnexpected(const Token& token, std::string_view expected) const;
  std::string shown(const Token& token) const;
  const std::string* name(std::string_view text) const { return intern(text); }

  // Statements (parser.cpp).
  Body subparse(std::initializer_list<std::string_view> endTokens);
  Body parseStatements(std::initializer_list<std::string_view> endTokens, bool dropNeedle);
  Stmt* parseStatement();
  Stmt* parseIf();
  Stmt* parseFor();
  Stmt* parseBlock();
  Stmt* parseExtends();
  Stmt* parseInclude();
  Stmt* parseImport();
  Stmt* parseFrom();
  Stmt* parseMacro();
  Stmt* parseCallBlock();
  Stmt* parseSet();
  Stmt* parseFilterBlock();
  Stmt* parseWith();
  Stmt* parsePrint();
  Stmt* parseDo();
  void parseSignature(MacroStmt* macro);
  bool parseContextFlag(bool& withContext);
  Expr* parseTemplateName();
  [[noreturn]] void failUnknownTag(const Token& token);
  [[noreturn]] void failEof();

  // Expressions (parser_expr.cpp).
  Expr* parseCondExpr();
  Expr* parseLogic(ExprKind kind, std::string_view word, Expr* (Parser::*operand)());
  Expr* parseOr();
  Expr* parseAnd();
  Expr* parseNot();
  Expr* parseCompare();
  Expr* parseMath1();
  Expr* parseConcat();
  Expr* parseMath2();
  Expr* parsePow();
  Expr* parseUnary(bool withFilter);
  Expr* parsePrimary();
  Expr* parseList();
  Expr* parseDict();
  Expr* parseCall(Expr* callee);
  Expr* parsePostfix(Expr* node);
  Expr* parseFilterExpr(Expr* node);
  Expr* parseSubscript(Expr* node);
  Expr* parseSubscribed();
  Expr* parseTest(Expr* node);
  Expr* parseStringLiteral();
  Expr* parseNumber(const Token& token);
  bool isTupleEnd(std::initializer_list<std::string_view> extraEnd) const;
  void enterNesting();

  struct OpenTag {
    std::string_view name;
    uint32_t pos;
  };

  std::string_view source_;
  const std::vector<Token>& tokens_;
  const Registry& registry_;
  Arena& arena_;
  size_t index_ = 0;
  int nesting_ = 0;
  std::vector<OpenTag> tagStack_;
  std::vector<std::vector<std::string_view>> endTokenStack_;
  std::vector<const std::string*> blockStack_;
  ParsedTemplate result_;

  friend class NestingGuard;
};

/// Bounds the nesting of expressions and statements so that no template overflows the stack.
class NestingGuard {
 public:
  explicit NestingGuard(Parser& parser, uint32_t pos);
  ~NestingGuard() { --parser_.nesting_; }
  NestingGuard(const NestingGuard&) = delete;
  NestingGuard& operator=(const NestingGuard&) = delete;

 private:
  Parser& parser_;
};

/// Decodes the body of a string literal token like Python's unicode-escape.
std::string unescapeString(std::string_view literal, uint32_t pos);

}  // namespace smachac::tmpl
