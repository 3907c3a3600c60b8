// AST traversal helpers (see ast_walk.h).
#include "backends/tmpl/ast/ast_walk.h"

namespace smachac::tmpl {
namespace {

void forEachArg(const ArgList& args, Visit<void(Expr*)> fn) {
  for (Expr* e : args.args) fn(e);
  for (const auto& kw : args.kwargs) fn(kw.second);
  if (args.dyn_args) fn(args.dyn_args);
  if (args.dyn_kwargs) fn(args.dyn_kwargs);
}

}  // namespace

void forEachChild(const Expr* expr, Visit<void(Expr*)> fn) {
  switch (expr->kind) {
    case ExprKind::Const:
    case ExprKind::Name:
      return;
    case ExprKind::List:
    case ExprKind::Tuple:
      for (Expr* e : static_cast<const SeqExpr*>(expr)->items) fn(e);
      return;
    case ExprKind::Dict:
      for (const auto& [k, v] : static_cast<const DictExpr*>(expr)->items) {
        fn(k);
        fn(v);
      }
      return;
    case ExprKind::Neg:
    case ExprKind::Pos:
    case ExprKind::Not:
      fn(static_cast<const UnaryExpr*>(expr)->operand);
      return;
    case ExprKind::Binary:
    case ExprKind::And:
    case ExprKind::Or: {
      auto* b = static_cast<const BinaryExpr*>(expr);
      fn(b->left);
      fn(b->right);
      return;
    }
    case ExprKind::Concat:
      for (Expr* e : static_cast<const ConcatExpr*>(expr)->items) fn(e);
      return;
    case ExprKind::Compare: {
      auto* c = static_cast<const CompareExpr*>(expr);
      fn(c->first);
      for (const auto& op : c->ops) fn(op.second);
      return;
    }
    case ExprKind::CondExpr: {
      auto* c = static_cast<const CondExpr*>(expr);
      fn(c->test);
      fn(c->then);
      if (c->otherwise) fn(c->otherwise);
      return;
    }
    case ExprKind::Getattr:
      fn(static_cast<const GetattrExpr*>(expr)->object);
      return;
    case ExprKind::Getitem: {
      auto* g = static_cast<const GetitemExpr*>(expr);
      fn(g->object);
      fn(g->index);
      return;
    }
    case ExprKind::Slice: {
      auto* s = static_cast<const SliceExpr*>(expr);
      for (Expr* e : {s->start, s->stop, s->step}) {
        if (e) fn(e);
      }
      return;
    }
    case ExprKind::Call: {
      auto* c = static_cast<const CallExpr*>(expr);
      fn(c->callee);
      forEachArg(c->args, fn);
      return;
    }
    case ExprKind::Filter: {
      auto* f = static_cast<const FilterExpr*>(expr);
      if (f->input) fn(f->input);
      forEachArg(f->args, fn);
      return;
    }
    case ExprKind::Test: {
      auto* t = static_cast<const TestExpr*>(expr);
      fn(t->input);
      forEachArg(t->args, fn);
      return;
    }
    case ExprKind::NamespaceRef:
      fn(static_cast<const NamespaceRefExpr*>(expr)->ns);
      return;
  }
}

void forEachPart(const Stmt* stmt, const StmtVisitor& v) {
  switch (stmt->kind) {
    case StmtKind::Text:
      return;
    case StmtKind::Print:
      v.expr(static_cast<const PrintStmt*>(stmt)->expr);
      return;
    case StmtKind::If: {
      auto* s = static_cast<const IfStmt*>(stmt);
      for (const auto& [test, body] : s->branches) {
        v.expr(test);
        v.body(body);
      }
      v.body(s->orelse);
      return;
    }
    case StmtKind::For: {
      auto* s = static_cast<const ForStmt*>(stmt);
      v.expr(s->target);
      v.expr(s->iter);
      v.body(s->body);
      v.body(s->orelse);
      if (s->filter) v.expr(s->filter);
      return;
    }
    case StmtKind::Block:
      v.body(static_cast<const BlockStmt*>(stmt)->body);
      return;
    case StmtKind::Extends:
      v.expr(static_cast<const ExtendsStmt*>(stmt)->template_name);
      return;
    case StmtKind::Include:
      v.expr(static_cast<const IncludeStmt*>(stmt)->template_name);
      return;
    case StmtKind::Import:
      v.expr(static_cast<const ImportStmt*>(stmt)->template_name);
      return;
    case StmtKind::FromImport:
      v.expr(static_cast<const FromImportStmt*>(stmt)->template_name);
      return;
    case StmtKind::Macro:
    case StmtKind::CallBlock: {
      auto* s = static_cast<const MacroStmt*>(stmt);
      if (stmt->kind == StmtKind::CallBlock) v.expr(static_cast<const CallBlockStmt*>(s)->call);
      for (Expr* p : s->params) v.expr(p);
      for (Expr* d : s->defaults) v.expr(d);
      v.body(s->body);
      return;
    }
    case StmtKind::Set: {
      auto* s = static_cast<const SetStmt*>(stmt);
      v.expr(s->target);
      v.expr(s->value);
      return;
    }
    case StmtKind::SetBlock: {
      auto* s = static_cast<const SetBlockStmt*>(stmt);
      v.expr(s->target);
      if (s->filter) v.expr(s->filter);
      v.body(s->body);
      return;
    }
    case StmtKind::FilterBlock: {
      auto* s = static_cast<const FilterBlockStmt*>(stmt);
      v.body(s->body);
      v.expr(s->filter);
      return;
    }
    case StmtKind::With: {
      auto* s = static_cast<const WithStmt*>(stmt);
      for (Expr* t : s->targets) v.expr(t);
      for (Expr* e : s->values) v.expr(e);
      v.body(s->body);
      return;
    }
    case StmtKind::Do:
      v.expr(static_cast<const DoStmt*>(stmt)->expr);
      return;
  }
}

}  // namespace smachac::tmpl
