// AST traversal helpers (see ast_walk.h).
#include "backends/tmpl/ast_walk.h"

namespace smachac::tmpl {
namespace {

void forEachArg(const ArgList& args, const std::function<void(Expr*)>& fn) {
  for (Expr* e : args.args) fn(e);
  for (const auto& kw : args.kwargs) fn(kw.second);
  if (args.dynArgs) fn(args.dynArgs);
  if (args.dynKwargs) fn(args.dynKwargs);
}

}  // namespace

void forEachChild(const Expr* expr, const std::function<void(Expr*)>& fn) {
  switch (expr->kind) {
    case ExprKind::kConst:
    case ExprKind::kName:
      return;
    case ExprKind::kList:
    case ExprKind::kTuple:
      for (Expr* e : static_cast<const SeqExpr*>(expr)->items) fn(e);
      return;
    case ExprKind::kDict:
      for (const auto& [k, v] : static_cast<const DictExpr*>(expr)->items) {
        fn(k);
        fn(v);
      }
      return;
    case ExprKind::kNeg:
    case ExprKind::kPos:
    case ExprKind::kNot:
      fn(static_cast<const UnaryExpr*>(expr)->operand);
      return;
    case ExprKind::kBinary:
    case ExprKind::kAnd:
    case ExprKind::kOr: {
      auto* b = static_cast<const BinaryExpr*>(expr);
      fn(b->left);
      fn(b->right);
      return;
    }
    case ExprKind::kConcat:
      for (Expr* e : static_cast<const ConcatExpr*>(expr)->items) fn(e);
      return;
    case ExprKind::kCompare: {
      auto* c = static_cast<const CompareExpr*>(expr);
      fn(c->first);
      for (const auto& op : c->ops) fn(op.second);
      return;
    }
    case ExprKind::kCondExpr: {
      auto* c = static_cast<const CondExpr*>(expr);
      fn(c->test);
      fn(c->then);
      if (c->otherwise) fn(c->otherwise);
      return;
    }
    case ExprKind::kGetattr:
      fn(static_cast<const GetattrExpr*>(expr)->object);
      return;
    case ExprKind::kGetitem: {
      auto* g = static_cast<const GetitemExpr*>(expr);
      fn(g->object);
      fn(g->index);
      return;
    }
    case ExprKind::kSlice: {
      auto* s = static_cast<const SliceExpr*>(expr);
      for (Expr* e : {s->start, s->stop, s->step}) {
        if (e) fn(e);
      }
      return;
    }
    case ExprKind::kCall: {
      auto* c = static_cast<const CallExpr*>(expr);
      fn(c->callee);
      forEachArg(c->args, fn);
      return;
    }
    case ExprKind::kFilter: {
      auto* f = static_cast<const FilterExpr*>(expr);
      if (f->input) fn(f->input);
      forEachArg(f->args, fn);
      return;
    }
    case ExprKind::kTest: {
      auto* t = static_cast<const TestExpr*>(expr);
      fn(t->input);
      forEachArg(t->args, fn);
      return;
    }
    case ExprKind::kNamespaceRef:
      fn(static_cast<const NamespaceRefExpr*>(expr)->ns);
      return;
  }
}

void forEachPart(const Stmt* stmt, const StmtVisitor& v) {
  switch (stmt->kind) {
    case StmtKind::kText:
      return;
    case StmtKind::kPrint:
      v.expr(static_cast<const PrintStmt*>(stmt)->expr);
      return;
    case StmtKind::kIf: {
      auto* s = static_cast<const IfStmt*>(stmt);
      for (const auto& [test, body] : s->branches) {
        v.expr(test);
        v.body(body);
      }
      v.body(s->orelse);
      return;
    }
    case StmtKind::kFor: {
      auto* s = static_cast<const ForStmt*>(stmt);
      v.expr(s->target);
      v.expr(s->iter);
      v.body(s->body);
      v.body(s->orelse);
      if (s->filter) v.expr(s->filter);
      return;
    }
    case StmtKind::kBlock:
      v.body(static_cast<const BlockStmt*>(stmt)->body);
      return;
    case StmtKind::kExtends:
      v.expr(static_cast<const ExtendsStmt*>(stmt)->templateName);
      return;
    case StmtKind::kInclude:
      v.expr(static_cast<const IncludeStmt*>(stmt)->templateName);
      return;
    case StmtKind::kImport:
      v.expr(static_cast<const ImportStmt*>(stmt)->templateName);
      return;
    case StmtKind::kFromImport:
      v.expr(static_cast<const FromImportStmt*>(stmt)->templateName);
      return;
    case StmtKind::kMacro:
    case StmtKind::kCallBlock: {
      auto* s = static_cast<const MacroStmt*>(stmt);
      if (stmt->kind == StmtKind::kCallBlock) v.expr(static_cast<const CallBlockStmt*>(s)->call);
      for (Expr* p : s->params) v.expr(p);
      for (Expr* d : s->defaults) v.expr(d);
      v.body(s->body);
      return;
    }
    case StmtKind::kSet: {
      auto* s = static_cast<const SetStmt*>(stmt);
      v.expr(s->target);
      v.expr(s->value);
      return;
    }
    case StmtKind::kSetBlock: {
      auto* s = static_cast<const SetBlockStmt*>(stmt);
      v.expr(s->target);
      if (s->filter) v.expr(s->filter);
      v.body(s->body);
      return;
    }
    case StmtKind::kFilterBlock: {
      auto* s = static_cast<const FilterBlockStmt*>(stmt);
      v.body(s->body);
      v.expr(s->filter);
      return;
    }
    case StmtKind::kWith: {
      auto* s = static_cast<const WithStmt*>(stmt);
      for (Expr* t : s->targets) v.expr(t);
      for (Expr* e : s->values) v.expr(e);
      v.body(s->body);
      return;
    }
    case StmtKind::kDo:
      v.expr(static_cast<const DoStmt*>(stmt)->expr);
      return;
  }
}

}  // namespace smachac::tmpl
