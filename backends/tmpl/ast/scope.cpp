// Scope analysis (see scope.h). Phase 1 mirrors Jinja2's symbol tracking per frame (which
// names a frame owns and how they are loaded); phase 2 walks the code in the order Jinja
// generates it and resolves each name against the finished tables.
#include "backends/tmpl/ast/scope.h"

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <span>

#include "backends/tmpl/ast/ast_walk.h"
#include "backends/tmpl/ast/scope_symbols.h"

namespace smachac::tmpl {
namespace {

using scopes::Load;
using scopes::Name;
using scopes::Symbols;

// Jinja's find_undeclared: which of `names` are loaded before any store, not entering blocks.
// Names are interned, so they are compared by address.
class UndeclaredFinder {
 public:
  explicit UndeclaredFinder(std::span<const Name> names) : names_(names.begin(), names.end()) {}

  void visitBody(const Body& body) {
    for (const Stmt* s : body) {
      if (s->kind == StmtKind::Block) continue;
      forEachPart(s, StmtVisitor{[this](Expr* e) { visitExpr(e); },
                                 [this](const Body& b) { visitBody(b); }});
    }
  }

  void visitExpr(const Expr* e) {
    if (e->kind == ExprKind::Name) {
      auto* n = static_cast<const NameExpr*>(e);
      auto it = std::find(names_.begin(), names_.end(), n->name);
      if (it == names_.end()) return;
      if (n->ctx == NameCtx::Load) {
        if (!has(n->name)) undeclared_.push_back(n->name);
      } else {
        names_.erase(it);
      }
      return;
    }
    forEachChild(e, [this](Expr* c) { visitExpr(c); });
  }

  bool has(Name name) const {
    return std::find(undeclared_.begin(), undeclared_.end(), name) != undeclared_.end();
  }

 private:
  std::vector<Name> names_;
  std::vector<Name> undeclared_;
};

bool undeclared(const Body& body, Name name) {
  UndeclaredFinder finder(std::span<const Name>(&name, 1));
  finder.visitBody(body);
  return finder.has(name);
}

bool containsScopedBlock(const Body& body) {
  bool found = false;
  for (const Stmt* s : body) {
    if (s->kind == StmtKind::Block && static_cast<const BlockStmt*>(s)->scoped) return true;
    forEachPart(s, StmtVisitor{[](Expr*) {},
                               [&](const Body& b) { found = found || containsScopedBlock(b); }});
    if (found) return true;
  }
  return false;
}

class Analyzer {
 public:
  void analyzeRoot(ParsedTemplate& parsed, FrameLayout& layout) {
    deferred_ = &parsed.deferred;
    Symbols& table = newTable(nullptr);
    for (Stmt* s : parsed.body) visitStmt(s, table);
    resolveBody(parsed.body, table, true);
    layout = layoutOf(table);
  }

 private:
  Symbols& newTable(const Symbols* parent) {
    tables_.push_back(std::make_unique<Symbols>(parent));
    return *tables_.back();
  }

  // --- phase 1: Jinja's FrameSymbolVisitor -----------------------------------------------

  void visitExpr(Expr* e, Symbols& sym, bool as_param = false) {
    if (e->kind == ExprKind::Name) {
      auto* n = static_cast<NameExpr*>(e);
      if (as_param || n->ctx == NameCtx::Param) {
        sym.declareParameter(n->name);
      } else if (n->ctx == NameCtx::Store) {
        sym.store(n->name);
      } else {
        sym.load(n->name);
      }
      return;
    }
    if (e->kind == ExprKind::NamespaceRef) {
      sym.load(static_cast<NamespaceRefExpr*>(e)->ns->name);
      return;
    }
    forEachChild(e, [&](Expr* c) { visitExpr(c, sym, as_param); });
  }

  void visitBody(const Body& body, Symbols& sym) {
    for (Stmt* s : body) visitStmt(s, sym);
  }

  // One if/elif chain element the way Jinja nests elifs: test, then body/elif/else branches.
  void visitIf(Expr* test, const Body& body, Symbols& sym) {
    visitExpr(test, sym);
    Symbols body_sym = sym;
    visitBody(body, body_sym);
    sym.branchUpdate({&body_sym, nullptr, nullptr});  // no elif or else of its own
  }

  void visitStmt(Stmt* stmt, Symbols& sym) {
    switch (stmt->kind) {
      case StmtKind::Text:
      case StmtKind::Block:
        return;
      case StmtKind::If: {
        auto* s = static_cast<IfStmt*>(stmt);
        visitExpr(s->branches[0].first, sym);
        Symbols body_sym = sym;
        visitBody(s->branches[0].second, body_sym);
        std::optional<Symbols> elif_sym;  // copies only for the branches there are
        if (s->branches.size() > 1) elif_sym.emplace(sym);
        for (size_t i = 1; i < s->branches.size(); ++i) {
          visitIf(s->branches[i].first, s->branches[i].second, *elif_sym);
        }
        std::optional<Symbols> else_sym;
        if (!s->orelse.empty()) {
          else_sym.emplace(sym);
          visitBody(s->orelse, *else_sym);
        }
        sym.branchUpdate(
            {&body_sym, elif_sym ? &*elif_sym : nullptr, else_sym ? &*else_sym : nullptr});
        return;
      }
      case StmtKind::For:
        visitExpr(static_cast<ForStmt*>(stmt)->iter, sym);
        return;
      case StmtKind::Macro:
        sym.store(static_cast<MacroStmt*>(stmt)->name);
        return;
      case StmtKind::CallBlock:
        visitExpr(static_cast<CallBlockStmt*>(stmt)->call, sym);
        return;
      case StmtKind::FilterBlock:
        visitExpr(static_cast<FilterBlockStmt*>(stmt)->filter, sym);
        return;
      case StmtKind::With:
        for (Expr* v : static_cast<WithStmt*>(stmt)->values) visitExpr(v, sym);
        return;
      case StmtKind::SetBlock:
        visitExpr(static_cast<SetBlockStmt*>(stmt)->target, sym);
        return;
      case StmtKind::Set: {
        auto* s = static_cast<SetStmt*>(stmt);
        visitExpr(s->value, sym);
        visitExpr(s->target, sym);
        return;
      }
      case StmtKind::Import: {
        auto* s = static_cast<ImportStmt*>(stmt);
        visitExpr(s->template_name, sym);
        sym.store(s->target->name);
        return;
      }
      case StmtKind::FromImport: {
        auto* s = static_cast<FromImportStmt*>(stmt);
        visitExpr(s->template_name, sym);
        for (const ImportedName& n : s->names) sym.store(n.alias->name);
        return;
      }
      default:
        forEachPart(stmt, StmtVisitor{[&](Expr* e) { visitExpr(e, sym); },
                                      [&](const Body& b) { visitBody(b, sym); }});
    }
  }

  // --- phase 2: resolution in code-generation order ----------------------------------------

  SlotRef refFor(Name n, Symbols& sym) {
    const Symbols* owner = sym.findRef(n);
    if (!owner) {
      sym.defineRef(n, {SlotInitKind::Resolve});
      owner = &sym;
    }
    return SlotRef{static_cast<uint16_t>(sym.level - owner->level), owner->slotOf(n), true};
  }

  void resolveExpr(Expr* e, Symbols& sym) {
    if (e->kind == ExprKind::Name) {
      auto* n = static_cast<NameExpr*>(e);
      n->ref = refFor(n->name, sym);
      return;
    }
    forEachChild(e, [&](Expr* c) { resolveExpr(c, sym); });
  }

  std::vector<LocalRef> localsOf(Symbols& sym) {
    std::vector<LocalRef> out;
    for (Name n : sym.dumpStores()) out.push_back({n, refFor(n, sym)});
    return out;
  }

  void resolveBody(const Body& body, Symbols& sym, bool root) {
    for (Stmt* s : body) resolveStmt(s, sym, root);
  }

  void resolveStmt(Stmt* stmt, Symbols& sym, bool root) {
    switch (stmt->kind) {
      case StmtKind::Text:
        return;
      case StmtKind::Print:
        resolveExpr(static_cast<PrintStmt*>(stmt)->expr, sym);
        return;
      case StmtKind::If: {
        auto* s = static_cast<IfStmt*>(stmt);
        for (auto& [test, body] : s->branches) {
          resolveExpr(test, sym);
          resolveBody(body, sym, root);
        }
        resolveBody(s->orelse, sym, root);
        return;
      }
      case StmtKind::For:
        return analyzeFor(static_cast<ForStmt*>(stmt), sym);
      case StmtKind::Block: {
        auto* s = static_cast<BlockStmt*>(stmt);
        s->toplevel = root;
        if (s->scoped) s->locals = localsOf(sym);
        return analyzeBlock(s);
      }
      case StmtKind::Extends:
        if (!root) throw SyntaxFault{stmt->pos, "`extends` can only be used at the top level"};
        resolveExpr(static_cast<ExtendsStmt*>(stmt)->template_name, sym);
        return;
      case StmtKind::Include: {
        auto* s = static_cast<IncludeStmt*>(stmt);
        resolveExpr(s->template_name, sym);
        if (s->with_context) s->locals = localsOf(sym);
        return;
      }
      case StmtKind::Import: {
        auto* s = static_cast<ImportStmt*>(stmt);
        resolveExpr(s->template_name, sym);
        if (s->with_context) s->locals = localsOf(sym);
        resolveExpr(s->target, sym);
        s->toplevel = root;
        return;
      }
      case StmtKind::FromImport: {
        auto* s = static_cast<FromImportStmt*>(stmt);
        resolveExpr(s->template_name, sym);
        if (s->with_context) s->locals = localsOf(sym);
        for (ImportedName& n : s->names) resolveExpr(n.alias, sym);
        s->toplevel = root;
        return;
      }
      case StmtKind::Macro: {
        auto* s = static_cast<MacroStmt*>(stmt);
        markCapturing(sym);
        resolveExpr(s->target, sym);
        s->toplevel = root;
        if (s->deferred) return keepRootScope(s, sym);
        return analyzeMacro(s, sym);
      }
      case StmtKind::CallBlock: {
        auto* s = static_cast<CallBlockStmt*>(stmt);
        markCapturing(sym);
        resolveExpr(s->call, sym);
        return analyzeMacro(s, sym);
      }
      case StmtKind::Set: {
        auto* s = static_cast<SetStmt*>(stmt);
        resolveExpr(s->value, sym);
        resolveExpr(s->target, sym);
        s->toplevel = root;
        return;
      }
      case StmtKind::SetBlock:
        return analyzeSetBlock(static_cast<SetBlockStmt*>(stmt), sym, root);
      case StmtKind::FilterBlock:
        return analyzeFilterBlock(static_cast<FilterBlockStmt*>(stmt), sym);
      case StmtKind::With:
        return analyzeWith(static_cast<WithStmt*>(stmt), sym);
      case StmtKind::Do:
        resolveExpr(static_cast<DoStmt*>(stmt)->expr, sym);
        return;
    }
  }

  static void markCapturing(const Symbols& sym) {
    for (const Symbols* s = &sym; s; s = s->parent) s->capturing = true;
  }

  // --- nested frames ---------------------------------------------------------------------

  void checkLoopNotAssigned(ForStmt* s) {
    checkNotLoop(s->target);
    checkNotLoopIn(s->body);
  }

  // Raises the error of a `loop` stored to in `e` (a loop's target, or any expression of its
  // body: a `set` or a nested loop's target).
  static void checkNotLoop(Expr* e) {
    if (e->kind == ExprKind::Name) {
      auto* n = static_cast<NameExpr*>(e);
      if (n->ctx != NameCtx::Load && *n->name == "loop") {
        throw SyntaxFault{e->pos, "cannot assign to the special `loop` variable"};
      }
      return;
    }
    forEachChild(e, [](Expr* c) { checkNotLoop(c); });
  }

  static void checkNotLoopIn(const Body& body) {
    for (Stmt* st : body) {
      forEachPart(st, StmtVisitor{[](Expr* e) { checkNotLoop(e); },
                                  [](const Body& b) { checkNotLoopIn(b); }});
    }
  }

  static void collectTargetNames(Expr* target, std::vector<NameExpr*>& out) {
    if (target->kind == ExprKind::Name) {
      out.push_back(static_cast<NameExpr*>(target));
      return;
    }
    forEachChild(target, [&](Expr* c) { collectTargetNames(c, out); });
  }

  void analyzeFor(ForStmt* s, Symbols& outer) {
    checkLoopNotAssigned(s);
    resolveExpr(s->iter, outer);
    Symbols& loop = newTable(&outer);
    Name loop_name = specials().loop;
    bool extended = undeclared(s->body, loop_name) || containsScopedBlock(s->body);
    if (extended) loop.declareParameter(loop_name);
    visitExpr(s->target, loop, true);
    visitBody(s->body, loop);
    Symbols& else_sym = newTable(&outer);
    visitBody(s->orelse, else_sym);
    Symbols& test = newTable(&outer);
    if (s->filter) {
      visitExpr(s->target, test, true);
      visitExpr(s->filter, test);
      resolveExpr(s->filter, test);
      std::vector<NameExpr*> names;
      collectTargetNames(s->target, names);
      for (NameExpr* n : names) s->test_target_slots.push_back(test.slotOf(n->name));
    }
    resolveExpr(s->target, loop);
    resolveBody(s->body, loop, false);
    resolveBody(s->orelse, else_sym, false);
    if (extended) s->loop_slot = loop.slotOf(loop_name);
    s->loop_frame = layoutOf(loop);
    s->else_frame = layoutOf(else_sym);
    s->test_frame = layoutOf(test);
  }

  void analyzeBlock(BlockStmt* s) {
    Symbols& sym = newTable(nullptr);
    Name super_name = specials().super;
    if (undeclared(s->body, super_name)) sym.declareParameter(super_name);
    visitBody(s->body, sym);
    resolveBody(s->body, sym, false);
    if (sym.owns(super_name)) s->super_slot = sym.slotOf(super_name);
    s->frame = layoutOf(sym);
  }

  // A deferred macro is top-level: its outer scope is the root's, as it is now (the root
  // only gains names later; the body's analysis reads names, slots and stores).
  void keepRootScope(MacroStmt* s, const Symbols& root) {
    for (DeferredMacro& d : *deferred_) {
      if (d.macro != s) continue;
      d.root_refs = root.refs;
      d.root_stores = root.stores;
    }
  }

 public:
  void analyzeDeferred(const DeferredMacro& d) {
    Symbols& root = newTable(nullptr);
    root.refs = d.root_refs;
    root.stores = d.root_stores;
    root.capturing = true;
    analyzeMacro(d.macro, root);
  }

 private:
  void analyzeMacro(MacroStmt* s, Symbols& outer) {
    Symbols& sym = newTable(&outer);
    const std::array<Name, 3>& specials = this->specials().of_macro;  // caller, kwargs, varargs
    Name caller = specials[0];
    UndeclaredFinder finder(specials);
    finder.visitBody(s->body);
    auto has_param = [&](Name n) {
      return std::any_of(s->params.begin(), s->params.end(),
                         [&](NameExpr* p) { return p->name == n; });
    };
    for (NameExpr* p : s->params) visitExpr(p, sym);
    for (Name special : specials) {
      if (finder.has(special) && !has_param(special)) sym.declareParameter(special);
    }
    if (finder.has(caller) && has_param(caller)) {
      size_t index = 0;
      while (s->params[index]->name != caller) ++index;
      if (index + s->defaults.size() < s->params.size()) {
        throw SyntaxFault{s->params[index]->pos,
                          "the special `caller` argument must be omitted or given a default"};
      }
    }
    for (Expr* d : s->defaults) visitExpr(d, sym);
    visitBody(s->body, sym);
    for (NameExpr* p : s->params) resolveExpr(p, sym);
    for (Expr* d : s->defaults) resolveExpr(d, sym);
    resolveBody(s->body, sym, false);
    auto slot_if_declared = [&](Name n) {
      return finder.has(n) && !has_param(n) ? static_cast<int>(sym.slotOf(n)) : -1;
    };
    s->caller_slot = slot_if_declared(caller);
    s->kwargs_slot = slot_if_declared(specials[1]);
    s->varargs_slot = slot_if_declared(specials[2]);
    s->frame = layoutOf(sym);
  }

  void analyzeSetBlock(SetBlockStmt* s, Symbols& outer, bool root) {
    Symbols& sym = newTable(&outer);
    visitBody(s->body, sym);
    if (s->filter) visitExpr(s->filter, sym);
    resolveBody(s->body, sym, false);
    if (s->filter) resolveExpr(s->filter, sym);
    resolveExpr(s->target, outer);
    s->toplevel = root;
    s->frame = layoutOf(sym);
  }

  void analyzeFilterBlock(FilterBlockStmt* s, Symbols& outer) {
    Symbols& sym = newTable(&outer);
    visitBody(s->body, sym);
    visitExpr(s->filter, sym);
    resolveBody(s->body, sym, false);
    resolveExpr(s->filter, sym);
    s->frame = layoutOf(sym);
  }

  void analyzeWith(WithStmt* s, Symbols& outer) {
    for (Expr* v : s->values) resolveExpr(v, outer);
    Symbols& sym = newTable(&outer);
    for (Expr* t : s->targets) visitExpr(t, sym);
    visitBody(s->body, sym);
    for (Expr* t : s->targets) resolveExpr(t, sym);
    resolveBody(s->body, sym, false);
    s->frame = layoutOf(sym);
  }

  static FrameLayout layoutOf(const Symbols& sym) {
    FrameLayout layout;
    layout.num_slots = static_cast<uint16_t>(sym.refs.size());
    layout.capturable = sym.capturing;
    layout.inits.reserve(sym.loads.size());
    for (const auto& [n, load] : sym.loads) {
      SlotInit init{load.kind, sym.slotOf(n), n, hashString(*n), {}};
      if (load.kind == SlotInitKind::Alias) {
        init.alias = SlotRef{static_cast<uint16_t>(sym.level - load.alias_owner->level),
                             load.alias_owner->slotOf(n), true};
      }
      layout.inits.push_back(init);
    }
    return layout;
  }

  // The names that bodies may use without declaring them, interned when first needed.
  struct SpecialNames {
    std::array<Name, 3> of_macro = {};  // caller, kwargs, varargs
    Name loop = nullptr;
    Name super = nullptr;
  };
  const SpecialNames& specials() {
    if (!specials_.loop) {
      specials_ = {
          {intern("caller"), intern("kwargs"), intern("varargs")}, intern("loop"), intern("super")};
    }
    return specials_;
  }

  std::vector<std::unique_ptr<Symbols>> tables_;
  std::vector<DeferredMacro>* deferred_ = nullptr;
  SpecialNames specials_;
};

}  // namespace

void analyzeScopes(ParsedTemplate& parsed, FrameLayout& root_frame) {
  Analyzer().analyzeRoot(parsed, root_frame);
}

void analyzeDeferredMacro(const DeferredMacro& deferred) { Analyzer().analyzeDeferred(deferred); }

}  // namespace smachac::tmpl
