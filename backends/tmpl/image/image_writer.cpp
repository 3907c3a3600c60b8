// Writes a template's image (image_format.h has the layout; this file is its reference: every
// node kind's fields in the order image_reader.cpp reads them back).
#include "backends/tmpl/image/image_writer.h"

#include <algorithm>
#include <bit>
#include <map>
#include <string>
#include <string_view>

#include "backends/tmpl/image/image_format.h"

namespace smachac::tmpl {
namespace {

using image::ConstKind;

class ImageWriter {
 public:
  ImageWriter(const Template& tmpl, std::vector<const MacroStmt*> deferred)
      : tmpl_(tmpl), deferred_(std::move(deferred)) {}

  std::vector<uint8_t> write() {
    templateFields();
    std::vector<uint8_t> content;
    std::swap(content, out_);
    tables();
    out_.insert(out_.end(), content.begin(), content.end());
    std::string_view body(reinterpret_cast<const char*>(out_.data()), out_.size());
    std::vector<uint8_t> image(image::kMagic, image::kMagic + 4);
    image.push_back(image::kVersion);
    fixed(image, tmpl_.source().size(), 4);
    fixed(image, image::imageHash(tmpl_.source()), 8);
    fixed(image, image::imageHash(body), 8);
    image.insert(image.end(), out_.begin(), out_.end());
    return image;
  }

 private:
  static void fixed(std::vector<uint8_t>& to, uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) to.push_back(static_cast<uint8_t>(value >> (8 * i)));
  }

  void num(uint64_t value) {
    while (value >= 0x80) {
      out_.push_back(static_cast<uint8_t>(value | 0x80));
      value >>= 7;
    }
    out_.push_back(static_cast<uint8_t>(value));
  }
  void flag(bool value) { out_.push_back(value ? 1 : 0); }
  void slot(int value) { num(static_cast<uint64_t>(value + 1)); }

  uint32_t stringIndex(std::string_view text) {
    auto [it, added] = string_index_.try_emplace(std::string(text), strings_.size());
    if (added) strings_.emplace_back(text);
    return it->second;
  }
  void str(std::string_view text) { num(stringIndex(text)); }
  void optionalName(const std::string* name) { num(name ? stringIndex(*name) + 1 : 0); }

  uint32_t indexIn(std::vector<uint32_t>& table, const std::string& name) {
    uint32_t string = stringIndex(name);
    auto it = std::find(table.begin(), table.end(), string);
    if (it != table.end()) return static_cast<uint32_t>(it - table.begin());
    table.push_back(string);
    return static_cast<uint32_t>(table.size() - 1);
  }

  void tables() {
    num(strings_.size());
    for (const std::string& s : strings_) num(s.size());
    for (const std::string& s : strings_) out_.insert(out_.end(), s.begin(), s.end());
    for (const std::vector<uint32_t>* table : {&filters_, &tests_}) {
      num(table->size());
      for (uint32_t s : *table) num(s);
    }
  }

  void templateFields() {
    out_.push_back((tmpl_.hasExtends() ? image::kHasExtends : 0) |
                   (tmpl_.namesTemplates() ? image::kNamesTemplates : 0));
    num(tmpl_.references().size());
    for (const auto& [name, pos] : tmpl_.references()) {
      str(name);
      num(pos);
    }
    num(tmpl_.blocks().size());
    frame(tmpl_.rootFrame());
    body(tmpl_.body());
  }

  void ref(const SlotRef& r) {
    flag(r.valid);
    num(r.up);
    num(r.slot);
  }

  void frame(const FrameLayout& layout) {
    num(layout.num_slots);
    flag(layout.capturable);
    num(layout.inits.size());
    for (const SlotInit& init : layout.inits) {
      out_.push_back(static_cast<uint8_t>(init.kind));
      num(init.slot);
      str(*init.name);
      ref(init.alias);
    }
  }

  void locals(const std::vector<LocalRef>& refs) {
    num(refs.size());
    for (const LocalRef& local : refs) {
      str(*local.name);
      ref(local.ref);
    }
  }

  void exprs(const std::vector<Expr*>& items) {
    num(items.size());
    for (const Expr* e : items) expr(e);
  }

  void args(const ArgList& list) {
    exprs(list.args);
    num(list.kwargs.size());
    for (const auto& [name, value] : list.kwargs) {
      str(*name);
      expr(value);
    }
    expr(list.dyn_args);
    expr(list.dyn_kwargs);
  }

  void constant(const Value& v) {
    if (v.isNone()) {
      out_.push_back(static_cast<uint8_t>(ConstKind::None));
    } else if (v.isBool()) {
      out_.push_back(static_cast<uint8_t>(v.b() ? ConstKind::True : ConstKind::False));
    } else if (v.isInt()) {
      out_.push_back(static_cast<uint8_t>(ConstKind::Int));
      num(static_cast<uint64_t>(v.i()));
    } else if (v.isFloat()) {
      out_.push_back(static_cast<uint8_t>(ConstKind::Float));
      fixed(out_, std::bit_cast<uint64_t>(v.f()), 8);
    } else {
      out_.push_back(static_cast<uint8_t>(ConstKind::String));
      str(v.s());
    }
  }

  void expr(const Expr* e) {
    if (!e) {
      out_.push_back(image::kNullNode);
      return;
    }
    out_.push_back(static_cast<uint8_t>(e->kind));
    num(e->pos);
    exprFields(e);
  }

  void exprFields(const Expr* e) {
    switch (e->kind) {
      case ExprKind::Const:
        return constant(static_cast<const ConstExpr*>(e)->value);
      case ExprKind::Name: {
        auto* n = static_cast<const NameExpr*>(e);
        str(*n->name);
        out_.push_back(static_cast<uint8_t>(n->ctx));
        return ref(n->ref);
      }
      case ExprKind::List:
      case ExprKind::Tuple:
        return exprs(static_cast<const SeqExpr*>(e)->items);
      case ExprKind::Dict: {
        auto* d = static_cast<const DictExpr*>(e);
        num(d->items.size());
        for (const auto& [key, value] : d->items) {
          expr(key);
          expr(value);
        }
        return;
      }
      case ExprKind::Neg:
      case ExprKind::Pos:
      case ExprKind::Not:
        return expr(static_cast<const UnaryExpr*>(e)->operand);
      case ExprKind::Binary:
      case ExprKind::And:
      case ExprKind::Or: {
        auto* b = static_cast<const BinaryExpr*>(e);
        out_.push_back(static_cast<uint8_t>(b->op));
        expr(b->left);
        return expr(b->right);
      }
      default:
        return compoundFields(e);
    }
  }

  void compoundFields(const Expr* e) {
    switch (e->kind) {
      case ExprKind::Concat:
        return exprs(static_cast<const ConcatExpr*>(e)->items);
      case ExprKind::Compare: {
        auto* c = static_cast<const CompareExpr*>(e);
        expr(c->first);
        num(c->ops.size());
        for (const auto& [op, operand] : c->ops) {
          out_.push_back(static_cast<uint8_t>(op));
          expr(operand);
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
        return str(*g->attr);
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
        return callFields(e);
    }
  }

  void callFields(const Expr* e) {
    switch (e->kind) {
      case ExprKind::Call: {
        auto* c = static_cast<const CallExpr*>(e);
        expr(c->callee);
        return args(c->args);
      }
      case ExprKind::Filter: {
        auto* f = static_cast<const FilterExpr*>(e);
        expr(f->input);
        num(indexIn(filters_, *f->name));
        return args(f->args);
      }
      case ExprKind::Test: {
        auto* t = static_cast<const TestExpr*>(e);
        expr(t->input);
        num(indexIn(tests_, *t->name));
        return args(t->args);
      }
      default: {  // NamespaceRef
        auto* n = static_cast<const NamespaceRefExpr*>(e);
        expr(n->ns);
        return str(*n->attr);
      }
    }
  }

  void body(const Body& stmts) {
    num(stmts.size());
    for (const Stmt* s : stmts) stmt(s);
  }

  void stmt(const Stmt* s) {
    out_.push_back(static_cast<uint8_t>(s->kind));
    num(s->pos);
    switch (s->kind) {
      case StmtKind::Text: {
        std::string_view text = static_cast<const TextStmt*>(s)->text;
        num(static_cast<uint64_t>(text.data() - tmpl_.source().data()));
        return num(text.size());
      }
      case StmtKind::Print:
        return expr(static_cast<const PrintStmt*>(s)->expr);
      case StmtKind::Do:
        return expr(static_cast<const DoStmt*>(s)->expr);
      case StmtKind::Extends:
        return expr(static_cast<const ExtendsStmt*>(s)->template_name);
      case StmtKind::If: {
        auto* i = static_cast<const IfStmt*>(s);
        num(i->branches.size());
        for (const auto& [test, branch] : i->branches) {
          expr(test);
          body(branch);
        }
        return body(i->orelse);
      }
      case StmtKind::For:
        return forFields(static_cast<const ForStmt*>(s));
      case StmtKind::Block:
        return blockFields(static_cast<const BlockStmt*>(s));
      default:
        return importFields(s);
    }
  }

  void forFields(const ForStmt* f) {
    expr(f->target);
    expr(f->iter);
    expr(f->filter);
    flag(f->recursive);
    body(f->body);
    body(f->orelse);
    frame(f->loop_frame);
    frame(f->test_frame);
    frame(f->else_frame);
    slot(f->loop_slot);
    num(f->test_target_slots.size());
    for (uint16_t target : f->test_target_slots) num(target);
  }

  void blockFields(const BlockStmt* b) {
    str(*b->name);
    flag(b->scoped);
    flag(b->required);
    flag(b->toplevel);
    body(b->body);
    frame(b->frame);
    slot(b->super_slot);
    num(b->index);
    num(b->enclosing.size());
    for (const std::string* name : b->enclosing) str(*name);
    locals(b->locals);
  }

  void importFields(const Stmt* s) {
    switch (s->kind) {
      case StmtKind::Include: {
        auto* i = static_cast<const IncludeStmt*>(s);
        expr(i->template_name);
        flag(i->ignore_missing);
        flag(i->with_context);
        return locals(i->locals);
      }
      case StmtKind::Import: {
        auto* i = static_cast<const ImportStmt*>(s);
        expr(i->template_name);
        expr(i->target);
        flag(i->with_context);
        flag(i->toplevel);
        return locals(i->locals);
      }
      case StmtKind::FromImport: {
        auto* f = static_cast<const FromImportStmt*>(s);
        expr(f->template_name);
        num(f->names.size());
        for (const ImportedName& n : f->names) {
          str(*n.name);
          expr(n.alias);
        }
        flag(f->with_context);
        flag(f->toplevel);
        return locals(f->locals);
      }
      default:
        return assignFields(s);
    }
  }

  void assignFields(const Stmt* s) {
    switch (s->kind) {
      case StmtKind::Set: {
        auto* set = static_cast<const SetStmt*>(s);
        expr(set->target);
        expr(set->value);
        return flag(set->toplevel);
      }
      case StmtKind::SetBlock: {
        auto* set = static_cast<const SetBlockStmt*>(s);
        expr(set->target);
        expr(set->filter);
        body(set->body);
        frame(set->frame);
        return flag(set->toplevel);
      }
      case StmtKind::FilterBlock: {
        auto* f = static_cast<const FilterBlockStmt*>(s);
        expr(f->filter);
        body(f->body);
        return frame(f->frame);
      }
      case StmtKind::With: {
        auto* w = static_cast<const WithStmt*>(s);
        exprs(w->targets);
        exprs(w->values);
        body(w->body);
        return frame(w->frame);
      }
      default:
        return macroFields(static_cast<const MacroStmt*>(s));
    }
  }

  // Macro and call block: the header, then the rest inline or, for a deferred macro, as a
  // record prefixed by its size.
  void macroFields(const MacroStmt* m) {
    optionalName(m->name);
    expr(m->target);
    flag(m->toplevel);
    bool deferred = std::find(deferred_.begin(), deferred_.end(), m) != deferred_.end();
    flag(deferred);
    if (!deferred) {
      macroRecord(m);
    } else {
      std::vector<uint8_t> outer;
      std::swap(outer, out_);
      macroRecord(m);
      std::swap(outer, out_);
      num(outer.size());
      out_.insert(out_.end(), outer.begin(), outer.end());
    }
    if (m->kind == StmtKind::CallBlock) expr(static_cast<const CallBlockStmt*>(m)->call);
  }

  void macroRecord(const MacroStmt* m) {
    num(m->params.size());
    for (const NameExpr* p : m->params) expr(p);
    exprs(m->defaults);
    body(m->body);
    frame(m->frame);
    slot(m->caller_slot);
    slot(m->kwargs_slot);
    slot(m->varargs_slot);
  }

  const Template& tmpl_;
  std::vector<const MacroStmt*> deferred_;
  std::vector<uint8_t> out_;
  std::vector<std::string> strings_;
  std::map<std::string, uint32_t, std::less<>> string_index_;
  std::vector<uint32_t> filters_;
  std::vector<uint32_t> tests_;
};

}  // namespace

std::vector<uint8_t> writeTemplateImage(const Template& tmpl) {
  std::vector<const MacroStmt*> deferred;
  for (const Stmt* s : tmpl.body()) {
    if (s->kind != StmtKind::Macro) continue;
    auto* macro = static_cast<const MacroStmt*>(s);
    if (!macro->deferred) continue;
    tmpl.completeMacro(*macro);
    deferred.push_back(macro);
  }
  return ImageWriter(tmpl, std::move(deferred)).write();
}

}  // namespace smachac::tmpl
