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

#include "backends/tmpl/value.h"
#include "backends/tmpl/value_ops.h"

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
enum class SlotInitKind : uint8_t { kParameter, kResolve, kAlias, kUndefined };

struct SlotInit {
  SlotInitKind kind;
  uint16_t slot;
  const std::string* name;
  size_t hash;    // hashString(*name), for context lookups
  SlotRef alias;  // kAlias: the outer variable copied in
};

/// The run-time layout of one scope level (template root, block, macro, loop body, ...).
struct FrameLayout {
  uint16_t numSlots = 0;
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
  kConst,
  kName,
  kList,
  kTuple,
  kDict,
  kNeg,
  kPos,
  kNot,
  kBinary,
  kAnd,
  kOr,
  kConcat,
  kCompare,
  kCondExpr,
  kGetattr,
  kGetitem,
  kSlice,
  kCall,
  kFilter,
  kTest,
  kNamespaceRef,
};

struct Expr {
  ExprKind kind;
  uint32_t pos;
  Expr(ExprKind k, uint32_t p) : kind(k), pos(p) {}
  virtual ~Expr() = default;
};

struct ConstExpr : Expr {
  Value value;
  ConstExpr(uint32_t p, Value v) : Expr(ExprKind::kConst, p), value(std::move(v)) {}
};

enum class NameCtx : uint8_t { kLoad, kStore, kParam };

struct NameExpr : Expr {
  const std::string* name;
  NameCtx ctx;
  SlotRef ref;
  NameExpr(uint32_t p, const std::string* n, NameCtx c)
      : Expr(ExprKind::kName, p), name(n), ctx(c) {}
};

struct SeqExpr : Expr {  // list and tuple literals, tuple targets
  std::vector<Expr*> items;
  SeqExpr(ExprKind k, uint32_t p) : Expr(k, p) {}
};

struct DictExpr : Expr {
  std::vector<std::pair<Expr*, Expr*>> items;
  explicit DictExpr(uint32_t p) : Expr(ExprKind::kDict, p) {}
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
  explicit ConcatExpr(uint32_t p) : Expr(ExprKind::kConcat, p) {}
};

enum class CmpOp : uint8_t { kEq, kNe, kLt, kLe, kGt, kGe, kIn, kNotIn };

struct CompareExpr : Expr {
  Expr* first;
  std::vector<std::pair<CmpOp, Expr*>> ops;
  CompareExpr(uint32_t p, Expr* f) : Expr(ExprKind::kCompare, p), first(f) {}
};

struct CondExpr : Expr {
  Expr* test;
  Expr* then;
  Expr* otherwise;  // may be null
  CondExpr(uint32_t p, Expr* t, Expr* a, Expr* b)
      : Expr(ExprKind::kCondExpr, p), test(t), then(a), otherwise(b) {}
};

struct GetattrExpr : Expr {
  Expr* object;
  const std::string* attr;
  GetattrExpr(uint32_t p, Expr* o, const std::string* a)
      : Expr(ExprKind::kGetattr, p), object(o), attr(a) {}
};

struct GetitemExpr : Expr {
  Expr* object;
  Expr* index;
  GetitemExpr(uint32_t p, Expr* o, Expr* i) : Expr(ExprKind::kGetitem, p), object(o), index(i) {}
};

struct SliceExpr : Expr {
  Expr* start;
  Expr* stop;
  Expr* step;
  SliceExpr(uint32_t p, Expr* a, Expr* b, Expr* c)
      : Expr(ExprKind::kSlice, p), start(a), stop(b), step(c) {}
};

struct ArgList {
  std::vector<Expr*> args;
  std::vector<std::pair<const std::string*, Expr*>> kwargs;
  Expr* dynArgs = nullptr;
  Expr* dynKwargs = nullptr;
};

struct CallExpr : Expr {
  Expr* callee;
  ArgList args;
  CallExpr(uint32_t p, Expr* c) : Expr(ExprKind::kCall, p), callee(c) {}
};

struct FilterExpr : Expr {
  Expr* input;  // null for the innermost filter of a filter block or block set
  const std::string* name;
  const FilterDef* def = nullptr;
  ArgList args;
  FilterExpr(uint32_t p, Expr* in, const std::string* n)
      : Expr(ExprKind::kFilter, p), input(in), name(n) {}
};

struct TestExpr : Expr {
  Expr* input;
  const std::string* name;
  const TestDef* def = nullptr;
  ArgList args;
  TestExpr(uint32_t p, Expr* in, const std::string* n)
      : Expr(ExprKind::kTest, p), input(in), name(n) {}
};

/// `ns.attr` as an assignment target.
struct NamespaceRefExpr : Expr {
  NameExpr* ns;
  const std::string* attr;
  NamespaceRefExpr(uint32_t p, NameExpr* n, const std::string* a)
      : Expr(ExprKind::kNamespaceRef, p), ns(n), attr(a) {}
};

// --- Statements ----------------------------------------------------------------------------

enum class StmtKind : uint8_t {
  kText,
  kPrint,
  kIf,
  kFor,
  kBlock,
  kExtends,
  kInclude,
  kImport,
  kFromImport,
  kMacro,
  kCallBlock,
  kSet,
  kSetBlock,
  kFilterBlock,
  kWith,
  kDo,
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
  TextStmt(uint32_t p, std::string_view t) : Stmt(StmtKind::kText, p), text(t) {}
};

struct PrintStmt : Stmt {
  Expr* expr;
  PrintStmt(uint32_t p, Expr* e) : Stmt(StmtKind::kPrint, p), expr(e) {}
};

struct IfStmt : Stmt {
  std::vector<std::pair<Expr*, Body>> branches;  // if + elifs
  Body orelse;
  explicit IfStmt(uint32_t p) : Stmt(StmtKind::kIf, p) {}
};

struct ForStmt : Stmt {
  Expr* target = nullptr;
  Expr* iter = nullptr;
  Expr* filter = nullptr;
  bool recursive = false;
  Body body;
  Body orelse;
  FrameLayout loopFrame;
  FrameLayout testFrame;
  FrameLayout elseFrame;
  int loopSlot = -1;                      // slot of `loop` in loopFrame when the body uses it
  std::vector<uint16_t> testTargetSlots;  // the loop filter's own slots for the target names
  explicit ForStmt(uint32_t p) : Stmt(StmtKind::kFor, p) {}
};

struct BlockStmt : Stmt {
  const std::string* name = nullptr;
  bool scoped = false;
  bool required = false;
  bool toplevel = false;  // the call site is at the template's top level
  Body body;
  FrameLayout frame;
  int superSlot = -1;
  uint16_t index = 0;                         // position in Template::blocks()
  std::vector<const std::string*> enclosing;  // names of the blocks it is nested in
  std::vector<LocalRef> locals;               // scoped blocks: the caller's locals
  explicit BlockStmt(uint32_t p) : Stmt(StmtKind::kBlock, p) {}
};

struct ExtendsStmt : Stmt {
  Expr* templateName;
  mutable const class Template* loaded = nullptr;  // cache for a constant name
  ExtendsStmt(uint32_t p, Expr* e) : Stmt(StmtKind::kExtends, p), templateName(e) {}
};

struct IncludeStmt : Stmt {
  Expr* templateName = nullptr;
  mutable const class Template* loaded = nullptr;  // cache for a constant name
  bool ignoreMissing = false;
  bool withContext = true;
  std::vector<LocalRef> locals;
  explicit IncludeStmt(uint32_t p) : Stmt(StmtKind::kInclude, p) {}
};

struct ImportStmt : Stmt {
  Expr* templateName = nullptr;
  mutable const class Template* loaded = nullptr;  // cache for a constant name
  NameExpr* target = nullptr;
  bool withContext = false;
  bool toplevel = false;
  std::vector<LocalRef> locals;
  explicit ImportStmt(uint32_t p) : Stmt(StmtKind::kImport, p) {}
};

struct ImportedName {
  const std::string* name;
  NameExpr* alias;
  mutable size_t exportIndex = 0;  // where the module exported it last time (a lookup hint)
};

struct FromImportStmt : Stmt {
  Expr* templateName = nullptr;
  mutable const class Template* loaded = nullptr;  // cache for a constant name
  std::vector<ImportedName> names;
  bool withContext = false;
  bool toplevel = false;
  std::vector<LocalRef> locals;
  explicit FromImportStmt(uint32_t p) : Stmt(StmtKind::kFromImport, p) {}
};

/// A macro or the caller body of a call block.
struct MacroStmt : Stmt {
  const std::string* name = nullptr;  // null for call blocks
  NameExpr* target = nullptr;
  std::vector<NameExpr*> params;
  std::vector<Expr*> defaults;  // for the last defaults.size() params
  Body body;
  FrameLayout frame;
  int callerSlot = -1;
  int kwargsSlot = -1;
  int varargsSlot = -1;
  bool toplevel = false;
  MacroStmt(StmtKind k, uint32_t p) : Stmt(k, p) {}
};

struct CallBlockStmt : MacroStmt {
  CallExpr* call = nullptr;
  explicit CallBlockStmt(uint32_t p) : MacroStmt(StmtKind::kCallBlock, p) {}
};

struct SetStmt : Stmt {
  Expr* target = nullptr;
  Expr* value = nullptr;
  bool toplevel = false;
  explicit SetStmt(uint32_t p) : Stmt(StmtKind::kSet, p) {}
};

struct SetBlockStmt : Stmt {
  Expr* target = nullptr;
  FilterExpr* filter = nullptr;  // outermost filter of the chain, or null
  Body body;
  FrameLayout frame;
  bool toplevel = false;
  explicit SetBlockStmt(uint32_t p) : Stmt(StmtKind::kSetBlock, p) {}
};

struct FilterBlockStmt : Stmt {
  FilterExpr* filter = nullptr;
  Body body;
  FrameLayout frame;
  explicit FilterBlockStmt(uint32_t p) : Stmt(StmtKind::kFilterBlock, p) {}
};

struct WithStmt : Stmt {
  std::vector<Expr*> targets;
  std::vector<Expr*> values;
  Body body;
  FrameLayout frame;
  explicit WithStmt(uint32_t p) : Stmt(StmtKind::kWith, p) {}
};

struct DoStmt : Stmt {
  Expr* expr;
  DoStmt(uint32_t p, Expr* e) : Stmt(StmtKind::kDo, p), expr(e) {}
};

/// Owns the nodes of one template.
class Arena {
 public:
  template <class T, class... Args>
  T* make(Args&&... args) {
    auto node = std::make_unique<T>(std::forward<Args>(args)...);
    T* raw = node.get();
    if constexpr (std::is_base_of_v<Expr, T>) {
      exprs_.push_back(std::move(node));
    } else {
      stmts_.push_back(std::move(node));
    }
    return raw;
  }

 private:
  std::vector<std::unique_ptr<Expr>> exprs_;
  std::vector<std::unique_ptr<Stmt>> stmts_;
};

}  // namespace smachac::tmpl
