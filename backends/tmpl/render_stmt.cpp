// Statement execution: output, control flow, assignments (exported at the top level like
// Jinja2's context.vars), macros, includes, imports, inheritance and block call sites.
#include "backends/tmpl/error.h"
#include "backends/tmpl/limits.h"
#include "backends/tmpl/render.h"
#include "backends/tmpl/value_ops.h"
#include "backends/tmpl/value_print.h"

namespace smachac::tmpl {
namespace {

void write(Site& site, std::string_view text) {
  size_t limit = activeLimits().stringBytes;
  if (site.out->size() + text.size() > limit) {
    fail("output too large (limit " + std::to_string(limit) + " bytes)");
  }
  site.out->append(text);
}

void writeValue(Site& site, const Value& v) {
  if (v.isString()) return write(site, v.s());
  std::string text;
  appendStr(text, v);
  write(site, text);
}

bool isPublic(const std::string* name) { return !name->empty() && name->front() != '_'; }

size_t countTargetNames(const Expr* target) {
  if (target->kind == ExprKind::kName) return 1;
  size_t n = 0;
  for (const Expr* item : static_cast<const SeqExpr*>(target)->items) n += countTargetNames(item);
  return n;
}

void storeName(Site& site, const NameExpr* n, const Value& value, bool toplevel) {
  site.frame->slot(n->ref) = value;
  if (!toplevel) return;
  Context& ctx = site.frame->context();
  ctx.setVar(n->name, value);
  if (isPublic(n->name)) ctx.exportName(n->name);
}

std::vector<Value> unpack(const Value& value, size_t expected) {
  std::vector<Value> items = iterate(value);
  if (items.size() > expected) {
    fail("too many values to unpack (expected " + std::to_string(expected) + ")");
  }
  if (items.size() < expected) {
    fail("not enough values to unpack (expected " + std::to_string(expected) + ", got " +
         std::to_string(items.size()) + ")");
  }
  return items;
}

// The context of an included or imported-with-context template: the includer's context
// plus the local variables visible at the include (Jinja's get_all() + locals).
Ref<Context> derivedContext(Exec& ex, Site& site, const std::vector<LocalRef>& locals) {
  std::vector<std::pair<const std::string*, Value>> values;
  for (const LocalRef& local : locals) {
    const Value& v = site.frame->slot(local.ref);
    if (!v.isMissing()) values.emplace_back(local.name, v);
  }
  return ex.adopt(new Context(&site.frame->context(), std::move(values)));
}

// Loads the template a statement names; constant names are resolved once per node.
const Template& templateOf(Exec& ex, Site& site, const Expr* name, const Template*& loaded) {
  if (loaded) return *loaded;
  const Template& tmpl = loadTemplate(ex, eval(ex, site, name));
  if (name->kind == ExprKind::kConst) loaded = &tmpl;
  return tmpl;
}

void execInclude(Exec& ex, Site& site, const IncludeStmt& s) {
  const Template* tmpl = nullptr;
  try {
    tmpl = &templateOf(ex, site, s.templateName, s.loaded);
  } catch (const Fault&) {
    if (s.ignoreMissing) return;
    throw;
  }
  if (!s.withContext) {
    Value module = defaultModule(ex, *tmpl);
    write(site, static_cast<const ModuleObject*>(module.object())->body());
    return;
  }
  Ref<Context> ctx = derivedContext(ex, site, s.locals);
  registerBlocks(ex, *ctx, *tmpl);
  renderRoot(ex, *tmpl, *ctx, *site.out);
}

Value importModule(Exec& ex, Site& site, const Expr* templateName, const Template*& loaded,
                   bool withContext, const std::vector<LocalRef>& locals) {
  const Template& tmpl = templateOf(ex, site, templateName, loaded);
  if (withContext) return makeModule(ex, tmpl, derivedContext(ex, site, locals));
  return defaultModule(ex, tmpl);
}

void storeImported(Site& site, const NameExpr* alias, const Value& value, bool toplevel) {
  site.frame->slot(alias->ref) = value;
  if (!toplevel) return;
  Context& ctx = site.frame->context();
  ctx.setVar(alias->name, value);
  if (isPublic(alias->name)) ctx.unexportName(alias->name);
}

void execFromImport(Exec& ex, Site& site, const FromImportStmt& s) {
  Value module = importModule(ex, site, s.templateName, s.loaded, s.withContext, s.locals);
  auto* m = static_cast<const ModuleObject*>(module.object());
  for (const ImportedName& n : s.names) {
    Value v;
    if (!m->getExport(n.name, n.exportIndex, v)) {
      v = Value::undefinedHint("the template `" + m->tmpl()->name() + "` does not export `" +
                               *n.name + "`");
    }
    storeImported(site, n.alias, v, s.toplevel);
  }
}

void execBlockCall(Exec& ex, Site& site, const BlockStmt& s) {
  if (s.toplevel && site.root && site.root->parent) return;
  if (ex.skipMask(*ex.tmpl)[s.index]) return;
  Context& ctx = site.frame->context();
  auto& blocks = ctx.blocks();
  for (size_t i = 0; i < blocks.size(); ++i) {
    if (blocks[i].name != s.name) continue;
    if (!s.scoped) return renderBlockAt(ex, ctx, i, *site.out);
    Ref<Context> derived = derivedContext(ex, site, s.locals);
    derived->blocks() = blocks;
    return renderBlockAt(ex, *derived, i, *site.out);
  }
}

void execExtends(Exec& ex, Site& site, const ExtendsStmt& s) {
  if (site.root->parent) fail("the template extends more than one template");
  const Template& parent = templateOf(ex, site, s.templateName, s.loaded);
  site.root->parent = &parent;
  site.root->extendsPos = s.pos;
  registerBlocks(ex, site.frame->context(), parent);
}

void execCallBlock(Exec& ex, Site& site, const CallBlockStmt& s) {
  if (site.suppressed()) return;
  Value caller = Value::object(new MacroObject(ex.tmpl, &s, site.frame));
  const CallExpr* call = s.call;
  Value fn = eval(ex, site, call->callee);
  OwnedArgs args;
  evalArgs(ex, site, call->args, args);
  args.keyword.emplace_back(intern("caller"), caller);
  writeValue(site, callValue(ex, fn, args.view()));
}

void execSetBlock(Exec& ex, Site& site, const SetBlockStmt& s) {
  FrameHolder frame(ex, site.frame, &site.frame->context(), s.frame);
  initFrame(*frame, s.frame, ex.registry);
  std::string buffer;
  Site inner{frame.get(), &buffer, site.root, false, false};
  execBody(ex, inner, s.body);
  Value value = Value::string(std::move(buffer));
  if (s.filter) value = applyFilterExpr(ex, inner, s.filter, &value);
  assignTarget(site, s.target, value, s.toplevel);
}

void execFilterBlock(Exec& ex, Site& site, const FilterBlockStmt& s) {
  FrameHolder frame(ex, site.frame, &site.frame->context(), s.frame);
  initFrame(*frame, s.frame, ex.registry);
  std::string buffer;
  Site inner{frame.get(), &buffer, site.root, false, site.outputCheck};
  execBody(ex, inner, s.body);
  Value value = Value::string(std::move(buffer));
  writeValue(site, applyFilterExpr(ex, inner, s.filter, &value));
}

void execWith(Exec& ex, Site& site, const WithStmt& s) {
  std::vector<Value> values;
  for (const Expr* e : s.values) values.push_back(eval(ex, site, e));
  FrameHolder frame(ex, site.frame, &site.frame->context(), s.frame);
  initFrame(*frame, s.frame, ex.registry);
  for (size_t i = 0; i < s.targets.size(); ++i)
    bindTarget(*frame, s.targets[i], values[i], nullptr);
  Site inner = site.inner(frame.get());
  execBody(ex, inner, s.body);
}

void execMacroDef(Exec& ex, Site& site, const MacroStmt& s) {
  Value macro = Value::object(new MacroObject(ex.tmpl, &s, site.frame));
  storeName(site, s.target, macro, s.toplevel);
}

// `{{ expr }}`; a macro called for printing renders straight into the output.
void execPrint(Exec& ex, Site& site, const Expr* expr) {
  if (expr->kind == ExprKind::kCall) {
    auto* call = static_cast<const CallExpr*>(expr);
    if (call->callee->kind == ExprKind::kName) {
      Value fn = eval(ex, site, call->callee);
      if (auto* macro = fn.isObject() ? dynamic_cast<const MacroObject*>(fn.object()) : nullptr) {
        OwnedArgs args;
        evalArgs(ex, site, call->args, args);
        try {
          return macro->callInto(ex, args.view(), *site.out);
        } catch (const Fault& fault) {
          throw ex.tmpl->error(call->pos, fault.message());
        }
      }
      OwnedArgs args;
      evalArgs(ex, site, call->args, args);
      try {
        return writeValue(site, callValue(ex, fn, args.view()));
      } catch (const Fault& fault) {
        throw ex.tmpl->error(call->pos, fault.message());
      }
    }
  }
  writeValue(site, eval(ex, site, expr));
}

void execStmtInner(Exec& ex, Site& site, const Stmt* stmt) {
  switch (stmt->kind) {
    case StmtKind::kText:
      if (!site.suppressed()) write(site, static_cast<const TextStmt*>(stmt)->text);
      return;
    case StmtKind::kPrint:
      if (!site.suppressed()) execPrint(ex, site, static_cast<const PrintStmt*>(stmt)->expr);
      return;
    case StmtKind::kIf: {
      auto* s = static_cast<const IfStmt*>(stmt);
      for (const auto& [test, body] : s->branches) {
        if (truthy(eval(ex, site, test))) return execBody(ex, site, body);
      }
      return execBody(ex, site, s->orelse);
    }
    case StmtKind::kFor:
      return execFor(ex, site, *static_cast<const ForStmt*>(stmt));
    case StmtKind::kBlock:
      return execBlockCall(ex, site, *static_cast<const BlockStmt*>(stmt));
    case StmtKind::kExtends:
      return execExtends(ex, site, *static_cast<const ExtendsStmt*>(stmt));
    case StmtKind::kInclude:
      return execInclude(ex, site, *static_cast<const IncludeStmt*>(stmt));
    case StmtKind::kImport: {
      auto* s = static_cast<const ImportStmt*>(stmt);
      Value module = importModule(ex, site, s->templateName, s->loaded, s->withContext, s->locals);
      return storeImported(site, s->target, module, s->toplevel);
    }
    case StmtKind::kFromImport:
      return execFromImport(ex, site, *static_cast<const FromImportStmt*>(stmt));
    case StmtKind::kMacro:
      return execMacroDef(ex, site, *static_cast<const MacroStmt*>(stmt));
    case StmtKind::kCallBlock:
      return execCallBlock(ex, site, *static_cast<const CallBlockStmt*>(stmt));
    case StmtKind::kSet: {
      auto* s = static_cast<const SetStmt*>(stmt);
      return assignTarget(site, s->target, eval(ex, site, s->value), s->toplevel);
    }
    case StmtKind::kSetBlock:
      return execSetBlock(ex, site, *static_cast<const SetBlockStmt*>(stmt));
    case StmtKind::kFilterBlock:
      return execFilterBlock(ex, site, *static_cast<const FilterBlockStmt*>(stmt));
    case StmtKind::kWith:
      return execWith(ex, site, *static_cast<const WithStmt*>(stmt));
    case StmtKind::kDo:
      eval(ex, site, static_cast<const DoStmt*>(stmt)->expr);
      return;
  }
}

}  // namespace

void execBody(Exec& ex, Site& site, const Body& body) {
  for (const Stmt* stmt : body) {
    try {
      execStmtInner(ex, site, stmt);
    } catch (const Fault& fault) {
      throw ex.tmpl->error(stmt->pos, fault.message());
    }
  }
}

void initFrame(Frame& frame, const FrameLayout& layout, const Registry& registry) {
  for (const SlotInit& init : layout.inits) {
    switch (init.kind) {
      case SlotInitKind::kParameter:
        break;
      case SlotInitKind::kResolve:
        frame.local(init.slot) = frame.context().resolve(init.name, init.hash, registry);
        break;
      case SlotInitKind::kAlias:
        frame.local(init.slot) = frame.slot(init.alias);
        break;
      case SlotInitKind::kUndefined:
        frame.local(init.slot) = Value::missing(init.name);
        break;
    }
  }
}

void assignTarget(Site& site, const Expr* target, const Value& value, bool toplevel) {
  switch (target->kind) {
    case ExprKind::kName:
      return storeName(site, static_cast<const NameExpr*>(target), value, toplevel);
    case ExprKind::kTuple: {
      const auto& items = static_cast<const SeqExpr*>(target)->items;
      std::vector<Value> values = unpack(value, items.size());
      for (size_t i = 0; i < items.size(); ++i) assignTarget(site, items[i], values[i], toplevel);
      return;
    }
    case ExprKind::kNamespaceRef: {
      auto* ref = static_cast<const NamespaceRefExpr*>(target);
      const Value& ns = site.frame->slot(ref->ns->ref);
      if (!setNamespaceAttribute(ns, *ref->attr, value)) {
        fail("cannot assign an attribute to a non-namespace object");
      }
      return;
    }
    default:
      fail("cannot assign to this expression");
  }
}

void bindTarget(Frame& frame, const Expr* target, const Value& value, const uint16_t* slots) {
  if (target->kind == ExprKind::kName) {
    auto* n = static_cast<const NameExpr*>(target);
    (slots ? frame.local(*slots) : frame.slot(n->ref)) = value;
    return;
  }
  const auto& items = static_cast<const SeqExpr*>(target)->items;
  std::vector<Value> values = unpack(value, items.size());
  size_t offset = 0;
  for (size_t i = 0; i < items.size(); ++i) {
    bindTarget(frame, items[i], values[i], slots ? slots + offset : nullptr);
    if (slots) offset += countTargetNames(items[i]);
  }
}

}  // namespace smachac::tmpl
