// A text dump of a compiled template for tests: every field of every node (ast.h), the scope
// analysis' slots and frame layouts included, and the template's own fields. Written apart
// from the image writer so that a field the writer forgets shows as a difference. Names are
// shown as text, marked `!` when the pointer is not the interned one; a filter or test as its
// name and its definition's name.
#pragma once

#include <sstream>
#include <string>

#include "backends/tmpl/template.h"

namespace smachac::tmpl::testing {

class AstDump {
 public:
  std::string dump(const Template& t) {
    out_ << "extends=" << t.hasExtends() << " names=" << t.namesTemplates() << "\n";
    for (const auto& [name, pos] : t.references()) out_ << "ref " << name << "@" << pos << "\n";
    for (const BlockStmt* b : t.blocks())
      out_ << "block " << name(b->name) << "@" << b->pos << "\n";
    frame("root", t.rootFrame());
    body(t.body(), t.source());
    return out_.str();
  }

 private:
  std::string name(const std::string* n) {
    if (!n) return "<null>";
    return (n == intern(*n) ? "" : "!") + *n;
  }
  void ref(const SlotRef& r) { out_ << "[" << r.valid << " " << r.up << " " << r.slot << "]"; }
  void frame(const char* what, const FrameLayout& f) {
    out_ << what << "{" << f.num_slots << " " << f.capturable;
    for (const SlotInit& i : f.inits) {
      out_ << " (" << int(i.kind) << " " << i.slot << " " << name(i.name) << " "
           << (i.hash == hashString(*i.name));
      ref(i.alias);
      out_ << ")";
    }
    out_ << "}\n";
  }
  void locals(const std::vector<LocalRef>& refs) {
    for (const LocalRef& l : refs) {
      out_ << " local " << name(l.name);
      ref(l.ref);
    }
    out_ << "\n";
  }
  void args(const ArgList& a) {
    out_ << "(";
    for (const Expr* e : a.args) expr(e);
    for (const auto& [n, e] : a.kwargs) {
      out_ << name(n) << "=";
      expr(e);
    }
    out_ << "*";
    expr(a.dyn_args);
    out_ << "**";
    expr(a.dyn_kwargs);
    out_ << ")";
  }
  void constant(const Value& v) {
    if (v.isNone()) out_ << "None";
    if (v.isBool()) out_ << "bool:" << v.b();
    if (v.isInt()) out_ << "int:" << v.i();
    if (v.isFloat()) out_ << "float:" << v.f();
    if (v.isString()) out_ << "str:'" << v.s() << "'" << v.isMarkup();
  }

  void expr(const Expr* e) {
    if (!e) {
      out_ << "_ ";
      return;
    }
    out_ << "<" << int(e->kind) << "@" << e->pos << " ";
    switch (e->kind) {
      case ExprKind::Const:
        constant(static_cast<const ConstExpr*>(e)->value);
        break;
      case ExprKind::Name: {
        auto* n = static_cast<const NameExpr*>(e);
        out_ << name(n->name) << " " << int(n->ctx);
        ref(n->ref);
        break;
      }
      case ExprKind::List:
      case ExprKind::Tuple:
        for (const Expr* i : static_cast<const SeqExpr*>(e)->items) expr(i);
        break;
      case ExprKind::Dict:
        for (const auto& [k, v] : static_cast<const DictExpr*>(e)->items) {
          expr(k);
          expr(v);
        }
        break;
      case ExprKind::Neg:
      case ExprKind::Pos:
      case ExprKind::Not:
        expr(static_cast<const UnaryExpr*>(e)->operand);
        break;
      case ExprKind::Binary:
      case ExprKind::And:
      case ExprKind::Or: {
        auto* b = static_cast<const BinaryExpr*>(e);
        out_ << int(b->op) << " ";
        expr(b->left);
        expr(b->right);
        break;
      }
      default:
        compound(e);
    }
    out_ << "> ";
  }

  void compound(const Expr* e) {
    switch (e->kind) {
      case ExprKind::Concat:
        for (const Expr* i : static_cast<const ConcatExpr*>(e)->items) expr(i);
        return;
      case ExprKind::Compare: {
        auto* c = static_cast<const CompareExpr*>(e);
        expr(c->first);
        for (const auto& [op, o] : c->ops) {
          out_ << int(op) << " ";
          expr(o);
        }
        return;
      }
      case ExprKind::CondExpr: {
        auto* c = static_cast<const CondExpr*>(e);
        expr(c->test);
        expr(c->then);
        return expr(c->otherwise);
      }
      case ExprKind::Getattr: {
        auto* g = static_cast<const GetattrExpr*>(e);
        expr(g->object);
        out_ << "." << name(g->attr);
        return;
      }
      case ExprKind::Getitem: {
        auto* g = static_cast<const GetitemExpr*>(e);
        expr(g->object);
        return expr(g->index);
      }
      case ExprKind::Slice: {
        auto* s = static_cast<const SliceExpr*>(e);
        expr(s->start);
        expr(s->stop);
        return expr(s->step);
      }
      default:
        return call(e);
    }
  }

  void call(const Expr* e) {
    switch (e->kind) {
      case ExprKind::Call: {
        auto* c = static_cast<const CallExpr*>(e);
        expr(c->callee);
        return args(c->args);
      }
      case ExprKind::Filter: {
        auto* f = static_cast<const FilterExpr*>(e);
        expr(f->input);
        out_ << "|" << name(f->name) << ":" << (f->def ? f->def->name : "<null>")
             << (f->mapped ? "mapped" : "");
        return args(f->args);
      }
      case ExprKind::Test: {
        auto* t = static_cast<const TestExpr*>(e);
        expr(t->input);
        out_ << " is " << name(t->name) << ":" << (t->def ? t->def->name : "<null>");
        return args(t->args);
      }
      default: {
        auto* n = static_cast<const NamespaceRefExpr*>(e);
        expr(n->ns);
        out_ << "." << name(n->attr);
      }
    }
  }

  void body(const Body& b, std::string_view source) {
    out_ << "{\n";
    for (const Stmt* s : b) stmt(s, source);
    out_ << "}\n";
  }

  void stmt(const Stmt* s, std::string_view source) {
    out_ << "stmt " << int(s->kind) << "@" << s->pos << " ";
    switch (s->kind) {
      case StmtKind::Text: {
        auto* t = static_cast<const TextStmt*>(s);
        out_ << (t->text.data() - source.data()) << "+" << t->text.size() << " "
             << (t->pieces != nullptr) << "\n";
        return;
      }
      case StmtKind::Print:
        expr(static_cast<const PrintStmt*>(s)->expr);
        break;
      case StmtKind::Do:
        expr(static_cast<const DoStmt*>(s)->expr);
        break;
      case StmtKind::Extends:
        expr(static_cast<const ExtendsStmt*>(s)->template_name);
        break;
      case StmtKind::If: {
        auto* i = static_cast<const IfStmt*>(s);
        for (const auto& [test, branch] : i->branches) {
          expr(test);
          body(branch, source);
        }
        out_ << "else ";
        body(i->orelse, source);
        break;
      }
      case StmtKind::For:
        return forStmt(static_cast<const ForStmt*>(s), source);
      case StmtKind::Block:
        return blockStmt(static_cast<const BlockStmt*>(s), source);
      default:
        return importStmt(s, source);
    }
    out_ << "\n";
  }

  void forStmt(const ForStmt* f, std::string_view source) {
    expr(f->target);
    expr(f->iter);
    expr(f->filter);
    out_ << f->recursive << " " << f->loop_slot << " " << int(f->sorted_items) << " [";
    for (uint16_t slot : f->test_target_slots) out_ << slot << " ";
    out_ << "]\n";
    body(f->body, source);
    body(f->orelse, source);
    frame("loop", f->loop_frame);
    frame("test", f->test_frame);
    frame("else", f->else_frame);
  }

  void blockStmt(const BlockStmt* b, std::string_view source) {
    out_ << name(b->name) << " " << b->scoped << b->required << b->toplevel << " " << b->super_slot
         << " " << b->index << " in";
    for (const std::string* n : b->enclosing) out_ << " " << name(n);
    locals(b->locals);
    body(b->body, source);
    frame("block", b->frame);
  }

  void importStmt(const Stmt* s, std::string_view source) {
    switch (s->kind) {
      case StmtKind::Include: {
        auto* i = static_cast<const IncludeStmt*>(s);
        expr(i->template_name);
        out_ << i->ignore_missing << i->with_context << (i->loaded != nullptr);
        return locals(i->locals);
      }
      case StmtKind::Import: {
        auto* i = static_cast<const ImportStmt*>(s);
        expr(i->template_name);
        expr(i->target);
        out_ << i->with_context << i->toplevel << (i->loaded != nullptr);
        return locals(i->locals);
      }
      case StmtKind::FromImport: {
        auto* f = static_cast<const FromImportStmt*>(s);
        expr(f->template_name);
        for (const ImportedName& n : f->names) {
          out_ << name(n.name) << " as ";
          expr(n.alias);
          out_ << n.export_hint << " ";
        }
        out_ << f->with_context << f->toplevel << (f->loaded != nullptr);
        return locals(f->locals);
      }
      default:
        return assignStmt(s, source);
    }
  }

  void assignStmt(const Stmt* s, std::string_view source) {
    switch (s->kind) {
      case StmtKind::Set: {
        auto* set = static_cast<const SetStmt*>(s);
        expr(set->target);
        expr(set->value);
        out_ << set->toplevel << "\n";
        return;
      }
      case StmtKind::SetBlock: {
        auto* set = static_cast<const SetBlockStmt*>(s);
        expr(set->target);
        expr(set->filter);
        out_ << set->toplevel << "\n";
        body(set->body, source);
        return frame("set", set->frame);
      }
      case StmtKind::FilterBlock: {
        auto* f = static_cast<const FilterBlockStmt*>(s);
        expr(f->filter);
        body(f->body, source);
        return frame("filter", f->frame);
      }
      case StmtKind::With: {
        auto* w = static_cast<const WithStmt*>(s);
        for (const Expr* t : w->targets) expr(t);
        out_ << "= ";
        for (const Expr* v : w->values) expr(v);
        body(w->body, source);
        return frame("with", w->frame);
      }
      default:
        return macroStmt(static_cast<const MacroStmt*>(s), source);
    }
  }

  void macroStmt(const MacroStmt* m, std::string_view source) {
    out_ << name(m->name) << " ";
    expr(m->target);
    out_ << m->toplevel << m->deferred << " " << m->caller_slot << " " << m->kwargs_slot << " "
         << m->varargs_slot << " params ";
    for (const NameExpr* p : m->params) expr(p);
    out_ << "defaults ";
    for (const Expr* d : m->defaults) expr(d);
    if (m->kind == StmtKind::CallBlock) expr(static_cast<const CallBlockStmt*>(m)->call);
    out_ << "\n";
    body(m->body, source);
    frame("macro", m->frame);
  }

  std::ostringstream out_;
};

/// Completes every deferred macro of `t` (as their first calls would), then dumps it.
inline std::string dumpWhole(const Template& t) {
  for (const Stmt* s : t.body()) {
    if (s->kind == StmtKind::Macro) t.completeMacro(*static_cast<const MacroStmt*>(s));
  }
  return AstDump().dump(t);
}

}  // namespace smachac::tmpl::testing
