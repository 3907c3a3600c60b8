// The abstract syntax tree of a parsed template. Nodes live in the template's arena and point
// into its source; `pos` is a byte offset for error locations. The scope analysis (scope.h)
// fills the slot references and frame layouts that the renderer uses instead of name lookups.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/tmpl/ast/arena.h"
#include "backends/tmpl/values/value.h"
#include "backends/tmpl/values/value_ops.h"

namespace smachac::tmpl {

struct FilterDef;
struct TestDef;

/// Where a variable lives at run time: `up` frames above the current one, slot `slot`.
struct SlotRef {
  uint16_t up = 0;
  uint16_t slot = 0;
  bool valid = false;
};

/// How a frame slot is initialised when the frame is entered (Jinja's load instructions).
enum class SlotInitKind : uint8_t { Parameter, Resolve, Alias, Undefined };

struct SlotInit {
  SlotInitKind kind;
  uint16_t slot;
  const std::string* name;
  size_t hash;    // hashString(*name), for context lookups
  SlotRef alias;  // kAlias: the outer variable copied in
};

/// The run-time layout of one scope level (template root, block, macro, loop body, ...).
struct FrameLayout {
  uint16_t num_slots = 0;
  bool capturable = false;  // a macro defined at this level or below may keep the frame alive
  std::vector<SlotInit> inits;
};

/// A local variable passed to an include/import "with context" (Jinja's dump_stores).
struct LocalRef {
  const std::string* name;
  SlotRef ref;
};

// --- Expressions ---------------------------------------------------------------------------

enum class ExprKind : uint8_t {
  Const,
  Name,
  List,
  Tuple,
  Dict,
  Neg,
  Pos,
  Not,
  Binary,
  And,
  Or,
  Concat,
  Compare,
  CondExpr,
  Getattr,
  Getitem,
  Slice,
  Call,
  Filter,
  Test,
  NamespaceRef,
};

struct Expr {
  ExprKind kind;
  uint32_t pos;
  Expr(ExprKind k, uint32_t p) : kind(k), pos(p) {}
  virtual ~Expr() = default;
};

struct ConstExpr : Expr {
  Value value;
  ConstExpr(uint32_t p, Value v) : Expr(ExprKind::Const, p), value(std::move(v)) {}
};

enum class NameCtx : uint8_t { Load, Store, Param };

struct NameExpr : Expr {
  const std::string* name;
  NameCtx ctx;
  SlotRef ref;
  NameExpr(uint32_t p, const std::string* n, NameCtx c)
      : Expr(ExprKind::Name, p), name(n), ctx(c) {}
};

struct SeqExpr : Expr {  // list and tuple literals, tuple targets
  std::vector<Expr*> items;
  SeqExpr(ExprKind k, uint32_t p) : Expr(k, p) {}
};

struct DictExpr : Expr {
  std::vector<std::pair<Expr*, Expr*>> items;
  explicit DictExpr(uint32_t p) : Expr(ExprKind::Dict, p) {}
};

struct UnaryExpr : Expr {  // kNeg, kPos, kNot
  Expr* operand;
  UnaryExpr(ExprKind k, uint32_t p, Expr* e) : Expr(k, p), operand(e) {}
};

struct BinaryExpr : Expr {  // kBinary (op), kAnd, kOr
  BinOp op;
  Expr* left;
  Expr* right;
  BinaryExpr(ExprKind k, uint32_t p, BinOp o, Expr* l, Expr* r)
      : Expr(k, p), op(o), left(l), right(r) {}
};

struct ConcatExpr : Expr {
  std::vector<Expr*> items;
  explicit ConcatExpr(uint32_t p) : Expr(ExprKind::Concat, p) {}
};

enum class CmpOp : uint8_t { Eq, Ne, Lt, Le, Gt, Ge, In, NotIn };

struct CompareExpr : Expr {
  Expr* first;
  std::vector<std::pair<CmpOp, Expr*>> ops;
  CompareExpr(uint32_t p, Expr* f) : Expr(ExprKind::Compare, p), first(f) {}
};

struct CondExpr : Expr {
  Expr* test;
  Expr* then;
  Expr* otherwise;  // may be null
  CondExpr(uint32_t p, Expr* t, Expr* a, Expr* b)
      : Expr(ExprKind::CondExpr, p), test(t), then(a), otherwise(b) {}
};

struct GetattrExpr : Expr {
  Expr* object;
  const std::string* attr;
  GetattrExpr(uint32_t p, Expr* o, const std::string* a)
      : Expr(ExprKind::Getattr, p), object(o), attr(a) {}
};

struct GetitemExpr : Expr {
  Expr* object;
  Expr* index;
  GetitemExpr(uint32_t p, Expr* o, Expr* i) : Expr(ExprKind::Getitem, p), object(o), index(i) {}
};

struct SliceExpr : Expr {
  Expr* start;
  Expr* stop;
  Expr* step;
  SliceExpr(uint32_t p, Expr* a, Expr* b, Expr* c)
      : Expr(ExprKind::Slice, p), start(a), stop(b), step(c) {}
};

struct ArgList {
  std::vector<Expr*> args;
  std::vector<std::pair<const std::string*, Expr*>> kwargs;
  Expr* dyn_args = nullptr;
  Expr* dyn_kwargs = nullptr;
};

struct CallExpr : Expr {
  Expr* callee;
  ArgList args;
  CallExpr(uint32_t p, Expr* c) : Expr(ExprKind::Call, p), callee(c) {}
};

struct FilterExpr : Expr {
  Expr* input;  // null for the innermost filter of a filter block or block set
  const std::string* name;
  const FilterDef* def = nullptr;
  ArgList args;
  /// `map('f')` under `join`: the definition of `f`, found at its first use (the renderer's).
  mutable const FilterDef* mapped = nullptr;
  FilterExpr(uint32_t p, Expr* in, const std::string* n)
      : Expr(ExprKind::Filter, p), input(in), name(n) {}
};

struct TestExpr : Expr {
  Expr* input;
  const std::string* name;
  const TestDef* def = nullptr;
  ArgList args;
  TestExpr(uint32_t p, Expr* in, const std::string* n)
      : Expr(ExprKind::Test, p), input(in), name(n) {}
};

/// `ns.attr` as an assignment target.
struct NamespaceRefExpr : Expr {
  NameExpr* ns;
  const std::string* attr;
  NamespaceRefExpr(uint32_t p, NameExpr* n, const std::string* a)
      : Expr(ExprKind::NamespaceRef, p), ns(n), attr(a) {}
};

// --- Statements ----------------------------------------------------------------------------

enum class StmtKind : uint8_t {
  Text,
  Print,
  If,
  For,
  Block,
  Extends,
  Include,
  Import,
  FromImport,
  Macro,
  CallBlock,
  Set,
  SetBlock,
  FilterBlock,
  With,
  Do,
};

struct Stmt {
  StmtKind kind;
  uint32_t pos;
  Stmt(StmtKind k, uint32_t p) : kind(k), pos(p) {}
  virtual ~Stmt() = default;
};

using Body = std::vector<Stmt*>;

struct TextStmt : Stmt {
  std::string_view text;
  /// A run of texts merged by a root plan (see SkipMask): the original statements, which run
  /// instead when the merged text would exceed the output limit (so the error names the same
  /// statement as without the plan).
  const Body* pieces = nullptr;
  TextStmt(uint32_t p, std::string_view t) : Stmt(StmtKind::Text, p), text(t) {}
};

struct PrintStmt : Stmt {
  Expr* expr;
  PrintStmt(uint32_t p, Expr* e) : Stmt(StmtKind::Print, p), expr(e) {}
};

struct IfStmt : Stmt {
  std::vector<std::pair<Expr*, Body>> branches;  // if + elifs
  Body orelse;
  explicit IfStmt(uint32_t p) : Stmt(StmtKind::If, p) {}
};

struct ForStmt : Stmt {
  Expr* target = nullptr;
  Expr* iter = nullptr;
  Expr* filter = nullptr;
  bool recursive = false;
  Body body;
  Body orelse;
  FrameLayout loop_frame;
  FrameLayout test_frame;
  FrameLayout else_frame;
  int loop_slot = -1;                       // slot of `loop` in loopFrame when the body uses it
  std::vector<uint16_t> test_target_slots;  // the loop filter's own slots for the target names
  /// Whether the loop is `for k, v in name.items() | sort` (loop.cpp; -1 until first run).
  mutable int8_t sorted_items = -1;
  explicit ForStmt(uint32_t p) : Stmt(StmtKind::For, p) {}
};

struct BlockStmt : Stmt {
  const std::string* name = nullptr;
  bool scoped = false;
  bool required = false;
  bool toplevel = false;  // the call site is at the template's top level
  Body body;
  FrameLayout frame;
  int super_slot = -1;
  uint16_t index = 0;                         // position in Template::blocks()
  std::vector<const std::string*> enclosing;  // names of the blocks it is nested in
  std::vector<LocalRef> locals;               // scoped blocks: the caller's locals
  explicit BlockStmt(uint32_t p) : Stmt(StmtKind::Block, p) {}
};

struct ExtendsStmt : Stmt {
  Expr* template_name;
  mutable const class Template* loaded = nullptr;  // cache for a constant name
  ExtendsStmt(uint32_t p, Expr* e) : Stmt(StmtKind::Extends, p), template_name(e) {}
};

struct IncludeStmt : Stmt {
  Expr* template_name = nullptr;
  mutable const class Template* loaded = nullptr;  // cache for a constant name
  bool ignore_missing = false;
  bool with_context = true;
  std::vector<LocalRef> locals;
  explicit IncludeStmt(uint32_t p) : Stmt(StmtKind::Include, p) {}
};

struct ImportStmt : Stmt {
  Expr* template_name = nullptr;
  mutable const class Template* loaded = nullptr;  // cache for a constant name
  NameExpr* target = nullptr;
  bool with_context = false;
  bool toplevel = false;
  std::vector<LocalRef> locals;
  explicit ImportStmt(uint32_t p) : Stmt(StmtKind::Import, p) {}
};

struct ImportedName {
  const std::string* name;
  NameExpr* alias;
  /// Where the name was in the exports of the module last imported (checked before use).
  mutable size_t export_hint = 0;
};

struct FromImportStmt : Stmt {
  Expr* template_name = nullptr;
  mutable const class Template* loaded = nullptr;  // cache for a constant name
  std::vector<ImportedName> names;
  bool with_context = false;
  bool toplevel = false;
  std::vector<LocalRef> locals;
  explicit FromImportStmt(uint32_t p) : Stmt(StmtKind::FromImport, p) {}
};

/// A macro or the caller body of a call block.
struct MacroStmt : Stmt {
  const std::string* name = nullptr;  // null for call blocks
  NameExpr* target = nullptr;
  std::vector<NameExpr*> params;
  std::vector<Expr*> defaults;  // for the last defaults.size() params
  Body body;
  FrameLayout frame;
  int caller_slot = -1;
  int kwargs_slot = -1;
  int varargs_slot = -1;
  bool toplevel = false;
  bool deferred = false;  // params, body, slots, frame not there yet (Template::completeMacro)
  MacroStmt(StmtKind k, uint32_t p) : Stmt(k, p) {}
};

struct CallBlockStmt : MacroStmt {
  CallExpr* call = nullptr;
  explicit CallBlockStmt(uint32_t p) : MacroStmt(StmtKind::CallBlock, p) {}
};

struct SetStmt : Stmt {
  Expr* target = nullptr;
  Expr* value = nullptr;
  bool toplevel = false;
  explicit SetStmt(uint32_t p) : Stmt(StmtKind::Set, p) {}
};

struct SetBlockStmt : Stmt {
  Expr* target = nullptr;
  FilterExpr* filter = nullptr;  // outermost filter of the chain, or null
  Body body;
  FrameLayout frame;
  bool toplevel = false;
  explicit SetBlockStmt(uint32_t p) : Stmt(StmtKind::SetBlock, p) {}
};

struct FilterBlockStmt : Stmt {
  FilterExpr* filter = nullptr;
  Body body;
  FrameLayout frame;
  explicit FilterBlockStmt(uint32_t p) : Stmt(StmtKind::FilterBlock, p) {}
};

struct WithStmt : Stmt {
  std::vector<Expr*> targets;
  std::vector<Expr*> values;
  Body body;
  FrameLayout frame;
  explicit WithStmt(uint32_t p) : Stmt(StmtKind::With, p) {}
};

struct DoStmt : Stmt {
  Expr* expr;
  DoStmt(uint32_t p, Expr* e) : Stmt(StmtKind::Do, p), expr(e) {}
};

/// Runs the destructors of the arena's nodes (arena.h), newest first.
inline Arena::~Arena() {
  for (auto it = stmts_.rbegin(); it != stmts_.rend(); ++it) (*it)->~Stmt();
  for (auto it = exprs_.rbegin(); it != exprs_.rend(); ++it) (*it)->~Expr();
}

}  // namespace smachac::tmpl
