// The parser: turns the token stream of one template into statements and expressions with
// Jinja2's grammar and precedence. Filters and tests are resolved against the registry here,
// so an unknown one is a syntax error with its location.
#pragma once

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "backends/tmpl/ast/ast.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/lexer/lexer.h"

namespace smachac::tmpl {

/// A top-level macro whose signature and body are parsed on its first call
/// (deferred_macro.cpp): where its signature's tokens start, and the names of the root scope
/// its body will see (scope.h).
struct DeferredMacro {
  MacroStmt* macro;
  size_t first_token;
  std::vector<const std::string*> root_refs;
  std::vector<const std::string*> root_stores;
};

/// What parsing one template produces.
struct ParsedTemplate {
  Body body;
  std::vector<BlockStmt*> blocks;                            // every block, in document order
  std::vector<std::pair<std::string, uint32_t>> references;  // literal names of extends etc.
  bool has_extends = false;
  bool names_templates = false;         // any extends, include or import, by a literal name or not
  std::vector<DeferredMacro> deferred;  // macros whose signature and body wait for a call
};

/// How parseTuple reads `a, b, c` (Jinja2's Parser.parse_tuple; the defaults are Jinja's).
struct TupleOptions {
  bool simplified = false;     // items are primaries only (names, literals): assignment targets
  bool with_cond_expr = true;  // items may be conditional expressions `x if c else y`
  std::initializer_list<std::string_view> extra_end = {};  // names that also end the tuple
  bool explicit_parens = false;  // inside `( )`, where `()` is the empty tuple
};

/// What parseAssignTarget accepts (Jinja2's Parser.parse_assign_target; Jinja's defaults).
struct AssignTargetOptions {
  bool with_tuple = true;  // `a, b` unpacks into several names
  bool name_only = false;  // exactly one name (macro parameters, import aliases)
  std::initializer_list<std::string_view> extra_end = {};  // names that end a target tuple
  bool with_namespace = false;                             // `ns.attr` (the `set` tag)
};

/// Whether parseStatements consumes the end tag it stops at, or leaves it current for the
/// caller to tell which one ended the body (`else` or `endfor`).
enum class EndTag { Keep, Consume };

/// Whether parseUnary also reads the filters and tests after its operand (`-x|abs` filters x).
enum class UnaryFilters { Parse, Leave };

/// Whether parseFilterChain starts at a `|` or, in `{% filter name %}`, at the filter name.
enum class FilterStart { AtPipe, AtName };

/// Parses `tokens` (of `source`); raises SyntaxFault. With `defer_macros`, the top-level
/// macros that can wait are left unparsed (ParsedTemplate::deferred).
ParsedTemplate parseTemplate(std::string_view source, std::span<const Token> tokens,
                             const Registry& registry, Arena& arena, bool defer_macros = false);

class Parser {
 public:
  Parser(std::string_view source, std::span<const Token> tokens, const Registry& registry,
         Arena& arena, bool defer_macros = false)
      : source_(source),
        tokens_(tokens),
        registry_(registry),
        arena_(arena),
        defer_macros_(defer_macros) {}

  ParsedTemplate parse();
  /// Fills the signature and body of a deferred macro, as the whole template's parse would
  /// have.
  void parseDeferredMacro(const DeferredMacro& deferred);

  // Expressions (parser_expr.cpp).
  /// `with_cond_expr` false: an `or` expression, where `if` ends it (tuples of a `for`).
  Expr* parseExpression(bool with_cond_expr = true);
  Expr* parseTuple(const TupleOptions& options);
  Expr* parseAssignTarget(const AssignTargetOptions& options);
  FilterExpr* parseFilterChain(Expr* input, FilterStart start);
  NameExpr* parseTargetName();
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
  /// Raises "expected `expected`, got ..." at the current token.
  [[noreturn, gnu::cold, gnu::noinline]] void failExpected(std::string_view expected) const;
  /// Raises `prefix` followed by how `token` is shown ("unexpected `)`"), at the token.
  [[noreturn, gnu::cold, gnu::noinline]] void failGot(const Token& token,
                                                      std::string_view prefix) const;
  [[noreturn]] void failUnexpected(const Token& token, std::string_view expected) const;
  std::string shown(const Token& token) const;
  const std::string* name(std::string_view text) const { return intern(text); }
  std::string_view textOf(const Token& token) const { return token.textIn(source_); }
  bool isName(const Token& token, std::string_view name) const {
    return token.is(Tok::Name) && textOf(token) == name;
  }

  // Statements (parser.cpp).
  Body subparse(std::initializer_list<std::string_view> end_tokens);
  Body parseStatements(std::initializer_list<std::string_view> end_tokens, EndTag end_tag);
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
  bool deferMacro(MacroStmt* macro);
  std::optional<size_t> deferrableBodyEnd(size_t first) const;
  bool knownFilterOrTestAt(size_t index) const;
  bool parseContextFlag(bool& with_context);
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
  Expr* parseUnary(UnaryFilters filters);
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
  bool isTupleEnd(std::initializer_list<std::string_view> extra_end) const;
  bool atLoneOperand() const;
  void enterNesting();

  struct OpenTag {
    std::string_view name;
    uint32_t pos;
  };

  std::string_view source_;
  std::span<const Token> tokens_;
  const Registry& registry_;
  Arena& arena_;
  bool defer_macros_;
  size_t index_ = 0;
  int nesting_ = 0;
  std::vector<OpenTag> tag_stack_;
  // The end tags of the bodies being parsed, for error messages: views of the callers'
  // initializer lists, which outlive the parse of their body (no copy per body).
  std::vector<std::span<const std::string_view>> end_token_stack_;
  std::vector<const std::string*> block_stack_;
  std::vector<Stmt*> body_scratch_;  // the statements of the bodies being parsed, innermost last
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
  [[noreturn, gnu::cold, gnu::noinline]] void failTooDeep(uint32_t pos) const;

  Parser& parser_;
};

/// Decodes the body of a string literal token like Python's unicode-escape.
std::string unescapeString(std::string_view literal, uint32_t pos);

}  // namespace smachac::tmpl
