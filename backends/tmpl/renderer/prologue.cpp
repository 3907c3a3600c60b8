// Recording and replaying render prologues (see prologue.h). The recorder mirrors what
// execBody does with each root statement under the skip policy; anything it does not mirror
// exactly makes the template's renders take the normal path.
#include "backends/tmpl/renderer/prologue.h"

#include "backends/tmpl/error.h"
#include "backends/tmpl/limits.h"
#include "backends/tmpl/renderer/render.h"

namespace smachac::tmpl {
namespace {

// More nested roots than this (an extends chain, or a cycle the normal run reports) are not
// recorded; the replay relies on it to stay far below the call depth limit.
constexpr size_t kMaxRoots = 16;

const Value* constantName(const Expr* name) {
  if (name->kind != ExprKind::Const) return nullptr;
  return &static_cast<const ConstExpr*>(name)->value;
}

class Recorder {
 public:
  Recorder(Exec& ex, RenderPrologue& out) : ex_(ex), out_(out) {}

  // One root statement of `owner`; false if the prologue cannot hold it. `parent` is set
  // once the root's extends ran (the root's output is suppressed from then on).
  bool record(const Template& owner, Stmt* stmt, const Template*& parent) {
    switch (stmt->kind) {
      case StmtKind::Text:
        if (!parent) addText(owner, stmt);
        return true;
      case StmtKind::Print:
        return parent != nullptr;  // suppressed: not even evaluated
      case StmtKind::FromImport:
        return recordImport(static_cast<const FromImportStmt&>(*stmt));
      case StmtKind::Include:
        return recordInclude(owner, static_cast<const IncludeStmt&>(*stmt));
      case StmtKind::Extends:
        return recordExtends(owner, static_cast<const ExtendsStmt&>(*stmt), parent);
      case StmtKind::Block: {
        auto& block = static_cast<const BlockStmt&>(*stmt);
        if (parent && block.toplevel) return true;  // after extends the parent places blocks
        if (block.scoped || !block.toplevel) return false;
        flushImports();
        add({PrologueStep::BlockCall, &owner, nullptr, stmt, {}, {}, {}});
        return true;
      }
      default:
        return false;
    }
  }

  void add(PrologueAction action) { out_.actions.push_back(std::move(action)); }
  /// A root text; one that follows another text of the same root (the imports between them
  /// move to the next block call) joins it, and the replay writes the run at once.
  void addText(const Template& owner, Stmt* stmt) {
    std::string_view text = static_cast<const TextStmt&>(*stmt).text;
    if (out_.actions.empty() || out_.actions.back().step != PrologueStep::Text ||
        out_.actions.back().owner != &owner) {
      add({PrologueStep::Text, &owner, nullptr, stmt, {stmt}, {}, std::string(text)});
      return;
    }
    out_.actions.back().body.push_back(stmt);
    out_.actions.back().text += text;
  }
  /// A root starts: its frame has no names yet.
  void enterRoot(const Template* owner, const Template& tmpl, const Stmt* via) {
    root_locals_.clear();
    add({PrologueStep::EnterRoot, owner, &tmpl, via, {}, {}, {}});
  }

  /// The imports recorded since the last block call (before it, or at the end).
  void flushImports() {
    if (imports_.vars.empty()) return;
    add({PrologueStep::Imports, nullptr, nullptr, nullptr, {}, std::move(imports_), {}});
    imports_ = SharedVars();
  }

 private:
  bool recordImport(const FromImportStmt& s) {
    const Value* name = constantName(s.template_name);
    if (!name || s.with_context || !s.toplevel) return false;
    Value module = defaultModule(ex_, loadTemplate(ex_, *name));
    auto* m = static_cast<const ModuleObject*>(module.object());
    for (const ImportedName& n : s.names) {
      size_t hint = 0;
      const Value* v = m->findExport(n.name, hint);
      if (!v) return false;  // the normal run binds an undefined value that explains itself
      bind(n.alias->name, *v);
      bindRootLocal(n.alias->name, *v);
    }
    out_.modules.push_back(std::move(module));
    return true;
  }

  // A name of the root frame (what an include passes as a local), the later binding winning.
  void bindRootLocal(const std::string* name, const Value& value) {
    for (auto& [n, v] : root_locals_) {
      if (n == name) {
        v = value;
        return;
      }
    }
    root_locals_.emplace_back(name, value);
  }

  // An imported name, bound (the later binding of a name wins) before the next block call.
  void bind(const std::string* name, const Value& value) {
    for (auto& [n, v] : imports_.vars) {
      if (n == name) {
        v = value;
        return;
      }
    }
    imports_.vars.emplace_back(name, value);
    imports_.names |= Context::nameBit(name);
  }

  bool recordInclude(const Template& owner, const IncludeStmt& s) {
    const Value* name = constantName(s.template_name);
    if (!name || !s.with_context) return false;
    const Template& included = loadTemplate(ex_, *name);
    const Body& body = rootBody(ex_, included);
    if (body.size() <= 1 && (body.empty() || body.front()->kind == StmtKind::Text)) {
      add({PrologueStep::IncludeText, &owner, &included, &s, body, {}, {}});
      return true;
    }
    // The locals the include passes: each must be a name this root imported before it.
    PrologueAction action{PrologueStep::Include, &owner, &included, &s, {}, {}, {}};
    for (const LocalRef& local : s.locals) {
      const Value* value = rootLocal(local.name);
      if (!value) return false;
      action.shared.vars.emplace_back(local.name, *value);
    }
    flushImports();  // the included root sees the context as the imports before it left it
    add(std::move(action));
    return true;
  }

  const Value* rootLocal(const std::string* name) const {
    for (const auto& [n, v] : root_locals_) {
      if (n == name) return &v;
    }
    return nullptr;
  }

  bool recordExtends(const Template& owner, const ExtendsStmt& s, const Template*& parent) {
    const Value* name = constantName(s.template_name);
    if (!name || parent) return false;
    parent = &loadTemplate(ex_, *name);
    add({PrologueStep::Blocks, &owner, parent, &s, {}, {}, {}});
    return true;
  }

  Exec& ex_;
  RenderPrologue& out_;
  SharedVars imports_;
  std::vector<std::pair<const std::string*, Value>> root_locals_;
};

// A root's call guard (renderRoot's CallGuard, kept until the replay ends); a fault entering
// a parent is located at the extends, as renderRoot locates it.
void enterRoot(Exec& ex, const PrologueAction& action) {
  try {
    ex.checkStack();
    ++ex.depth;
    ex.step();
  } catch (const Fault& fault) {
    if (!action.stmt) throw;
    throw action.owner->error(action.stmt->pos, fault.message());
  }
  ex.tmpl = action.tmpl;
}

// execBlockCall of a block that is neither skipped nor scoped.
void callBlock(Exec& ex, const PrologueAction& action, Context& ctx, std::string& out) {
  auto& block = static_cast<const BlockStmt&>(*action.stmt);
  try {
    auto& blocks = ctx.blocks();
    for (size_t i = 0; i < blocks.size(); ++i) {
      if (blocks[i].name == block.name) return renderBlockAt(ex, ctx, i, out);
    }
  } catch (const Fault& fault) {
    throw action.owner->error(block.pos, fault.message());
  }
}

// A root's text (or a run of them); one that would exceed the output limit runs as statements,
// which report it where the normal run does.
void writeText(Exec& ex, const PrologueAction& action, Site& site, size_t limit) {
  if (site.out->size() + action.text.size() <= limit) {
    site.out->append(action.text);
    return;
  }
  execBody(ex, site, action.body);
}

// execInclude of a template with more than a text: a derived context with the recorded locals.
void include(Exec& ex, const PrologueAction& action, Context& ctx, std::string& out) {
  try {
    Ref<Context> derived = ex.makeContext();
    derived->setOuter(&ctx);
    for (const auto& [name, value] : action.shared.vars) derived->addLocal(name, value);
    registerBlocks(ex, *derived, *action.tmpl);
    renderRoot(ex, *action.tmpl, *derived, out);
  } catch (const Fault& fault) {
    throw action.owner->error(action.stmt->pos, fault.message());
  }
}

void includeText(Exec& ex, const PrologueAction& action, Site& site) {
  try {
    CallGuard guard(ex, action.tmpl);
    execBody(ex, site, action.body);
  } catch (const Fault& fault) {
    throw action.owner->error(action.stmt->pos, fault.message());
  }
}

}  // namespace

std::shared_ptr<const RenderPrologue> recordPrologue(Exec& ex, const Template& tmpl) {
  auto prologue = std::make_shared<RenderPrologue>();
  Recorder recorder(ex, *prologue);
  try {
    const Template* current = &tmpl;
    const Template* owner = nullptr;
    const Stmt* via = nullptr;
    for (size_t roots = 0; current; ++roots) {
      if (roots == kMaxRoots) return nullptr;
      recorder.enterRoot(owner, *current, via);
      const Template* parent = nullptr;
      for (Stmt* stmt : rootBody(ex, *current)) {
        if (!recorder.record(*current, stmt, parent)) return nullptr;
        if (stmt->kind == StmtKind::Extends) via = stmt;
      }
      owner = current;
      current = parent;
    }
    recorder.flushImports();
  } catch (const std::exception&) {
    return nullptr;  // the normal run reports it where it happens
  }
  return prologue;
}

void replayPrologue(Exec& ex, const RenderPrologue& prologue, Context& ctx, std::string& out) {
  struct Restore {
    Exec& ex;
    const Template* tmpl;
    int depth;
    ~Restore() {
      ex.tmpl = tmpl;
      ex.depth = depth;
    }
  } restore{ex, ex.tmpl, ex.depth};
  Site site{nullptr, &out, nullptr, false, false};
  size_t limit = activeLimits().string_bytes;
  for (const PrologueAction& action : prologue.actions) {
    switch (action.step) {
      case PrologueStep::EnterRoot:
        enterRoot(ex, action);
        break;
      case PrologueStep::Text:
        writeText(ex, action, site, limit);
        break;
      case PrologueStep::IncludeText:
        includeText(ex, action, site);
        break;
      case PrologueStep::Include:
        include(ex, action, ctx, out);
        break;
      case PrologueStep::Imports:
        if (ctx.shareVars(action.shared)) break;
        for (const auto& [name, value] : action.shared.vars) ctx.setVar(name, value);
        break;
      case PrologueStep::Blocks:
        registerBlocks(ex, ctx, *action.tmpl);
        break;
      case PrologueStep::BlockCall:
        callBlock(ex, action, ctx, out);
        break;
    }
  }
}

}  // namespace smachac::tmpl
