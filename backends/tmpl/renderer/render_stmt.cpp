// Statement execution: output, control flow, assignments (exported at the top level like
// Jinja2's context.vars), macros, includes, imports, inheritance and block call sites.
#include <typeinfo>

#include "backends/tmpl/error.h"
#include "backends/tmpl/limits.h"
#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/string_ops.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::tmpl {
namespace {

[[noreturn]] void failOutputSize(size_t limit) {
  fail("output too large (limit " + std::to_string(limit) + " bytes)");
}

inline void checkOutputSize(size_t size) {
  size_t limit = activeLimits().string_bytes;
  if (size > limit) failOutputSize(limit);
}

// Inline: a render writes a text or a value for almost every statement it runs.
[[gnu::always_inline]] inline void write(Site& site, std::string_view text) {
  checkOutputSize(site.out->size() + text.size());
  reserveToAppend(*site.out, text.size());
  site.out->append(text);
}

// A text statement; a merged run of texts (RootPlan) that would exceed the output limit runs
// its pieces instead, so that the error names the same piece.
void writeText(Exec& ex, Site& site, const TextStmt& s) {
  if (s.pieces && site.out->size() + s.text.size() > activeLimits().string_bytes) {
    return execBody(ex, site, *s.pieces);
  }
  write(site, s.text);
}

void writeValue(Site& site, const Value& v) {
  if (v.isString()) return write(site, v.s());
  std::string text;
  appendStr(text, v);
  write(site, text);
}

bool isPublic(const std::string* name) { return !name->empty() && name->front() != '_'; }

size_t countTargetNames(const Expr* target) {
  if (target->kind == ExprKind::Name) return 1;
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
  Ref<Context> ctx = ex.makeContext();
  ctx->setOuter(&site.frame->context());
  for (const LocalRef& local : locals) {
    const Value& v = site.frame->slot(local.ref);
    if (!v.isMissing()) ctx->addLocal(local.name, v);
  }
  return ctx;
}

// Loads the template a statement names; constant names are resolved once per node.
const Template& templateOf(Exec& ex, Site& site, const Expr* name, const Template*& loaded) {
  if (loaded) return *loaded;
  const Template& tmpl = loadTemplate(ex, eval(ex, site, name));
  if (name->kind == ExprKind::Const) loaded = &tmpl;
  return tmpl;
}

void execInclude(Exec& ex, Site& site, const IncludeStmt& s) {
  const Template* tmpl = nullptr;
  try {
    tmpl = &templateOf(ex, site, s.template_name, s.loaded);
  } catch (const Fault&) {
    if (s.ignore_missing) return;
    throw;
  }
  if (!s.with_context) {
    Value module = defaultModule(ex, *tmpl);
    write(site, static_cast<const ModuleObject*>(module.object())->body());
    return;
  }
  const Body& body = rootBody(ex, *tmpl);
  if (body.size() <= 1 && (body.empty() || body.front()->kind == StmtKind::Text)) {
    // Its root is one text under this skip policy (SMACHA's includes of a block that is
    // skipped): nothing in it sees a context, so it writes the text without one.
    CallGuard guard(ex, tmpl);
    RootState root;
    Site inner{site.frame, site.out, &root, true, false};
    return execBody(ex, inner, body);
  }
  Ref<Context> ctx = derivedContext(ex, site, s.locals);
  registerBlocks(ex, *ctx, *tmpl);
  renderRoot(ex, *tmpl, *ctx, *site.out);
}

Value importModule(Exec& ex, Site& site, const Expr* template_name, const Template*& loaded,
                   bool with_context, const std::vector<LocalRef>& locals) {
  const Template& tmpl = templateOf(ex, site, template_name, loaded);
  if (with_context) return makeModule(ex, tmpl, derivedContext(ex, site, locals));
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
  Value module = importModule(ex, site, s.template_name, s.loaded, s.with_context, s.locals);
  auto* m = static_cast<const ModuleObject*>(module.object());
  Context* ctx = s.toplevel ? &site.frame->context() : nullptr;
  for (const ImportedName& n : s.names) {
    if (const Value* v = m->findExport(n.name, n.export_hint)) {
      // storeImported inline (a root's imports bind names by the dozen): the context only
      // ever exports public names, so unexporting a private one does nothing.
      site.frame->slot(n.alias->ref) = *v;
      if (!ctx) continue;
      ctx->setVar(n.alias->name, *v);
      ctx->unexportName(n.alias->name);
      continue;
    }
    storeImported(site, n.alias,
                  Value::undefinedHint("the template `" + m->tmpl()->name() +
                                       "` does not export `" + *n.name + "`"),
                  s.toplevel);
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
  const Template& parent = templateOf(ex, site, s.template_name, s.loaded);
  site.root->parent = &parent;
  site.root->extends_pos = s.pos;
  registerBlocks(ex, site.frame->context(), parent);
}

void execCallBlock(Exec& ex, Site& site, const CallBlockStmt& s) {
  if (site.suppressed()) return;
  Value caller = Value::object(new MacroObject(ex.tmpl, &s, site.frame));
  const CallExpr* call = s.call;
  Value fn = eval(ex, site, call->callee);
  OwnedArgs args;
  evalArgs(ex, site, call->args, args);
  args.keyword.emplaceBack(intern("caller"), caller);
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
  Site inner{frame.get(), &buffer, site.root, false, site.output_check};
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

// `{{ x | f(...) }}` with a filter that can write its result into the output itself.
void printFiltered(Exec& ex, Site& site, const FilterExpr* filter) {
  Value input = eval(ex, site, filter->input);
  OwnedArgs args;
  evalArgs(ex, site, filter->args, args);
  Value result;
  bool written = false;
  try {
    written = filter->def->into(ex, input, args.view(), *site.out);
    if (!written) result = applyFilter(ex, *filter->def, input, args.view());
  } catch (const Fault& fault) {
    throw ex.tmpl->error(filter->pos, fault.message());
  }
  if (!written) return writeValue(site, result);
  checkOutputSize(site.out->size());
}

// `{{ f(...) }}` of a name; a macro renders straight into the output. Out of line: its two
// argument lists and handlers would make every `{{ name }}` of execPrint pay their frame.
[[gnu::noinline]] void printCall(Exec& ex, Site& site, const CallExpr* call) {
  Value fn = eval(ex, site, call->callee);
  const Object* callee = fn.isObject() ? fn.object() : nullptr;
  // MacroObject is final: comparing the type is exact, and cheaper than a dynamic_cast.
  if (callee && typeid(*callee) == typeid(MacroObject)) {
    auto* macro = static_cast<const MacroObject*>(callee);
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

// `{{ expr }}`; a macro called for printing renders straight into the output, and so does a
// filter that can.
void execPrint(Exec& ex, Site& site, const Expr* expr) {
  if (expr->kind == ExprKind::Filter) {
    auto* filter = static_cast<const FilterExpr*>(expr);
    if (filter->input && filter->def->into) return printFiltered(ex, site, filter);
  }
  if (expr->kind == ExprKind::Call) {
    auto* call = static_cast<const CallExpr*>(expr);
    if (call->callee->kind == ExprKind::Name) return printCall(ex, site, call);
  }
  writeValue(site, eval(ex, site, expr));
}

void execStmtInner(Exec& ex, Site& site, const Stmt* stmt) {
  switch (stmt->kind) {
    case StmtKind::Text:
      if (!site.suppressed()) writeText(ex, site, *static_cast<const TextStmt*>(stmt));
      return;
    case StmtKind::Print:
      if (!site.suppressed()) execPrint(ex, site, static_cast<const PrintStmt*>(stmt)->expr);
      return;
    case StmtKind::If: {
      auto* s = static_cast<const IfStmt*>(stmt);
      for (const auto& [test, body] : s->branches) {
        if (truthy(eval(ex, site, test))) return execBody(ex, site, body);
      }
      return execBody(ex, site, s->orelse);
    }
    case StmtKind::For:
      return execFor(ex, site, *static_cast<const ForStmt*>(stmt));
    case StmtKind::Block:
      return execBlockCall(ex, site, *static_cast<const BlockStmt*>(stmt));
    case StmtKind::Extends:
      return execExtends(ex, site, *static_cast<const ExtendsStmt*>(stmt));
    case StmtKind::Include:
      return execInclude(ex, site, *static_cast<const IncludeStmt*>(stmt));
    case StmtKind::Import: {
      auto* s = static_cast<const ImportStmt*>(stmt);
      Value module =
          importModule(ex, site, s->template_name, s->loaded, s->with_context, s->locals);
      return storeImported(site, s->target, module, s->toplevel);
    }
    case StmtKind::FromImport:
      return execFromImport(ex, site, *static_cast<const FromImportStmt*>(stmt));
    case StmtKind::Macro:
      return execMacroDef(ex, site, *static_cast<const MacroStmt*>(stmt));
    case StmtKind::CallBlock:
      return execCallBlock(ex, site, *static_cast<const CallBlockStmt*>(stmt));
    case StmtKind::Set: {
      auto* s = static_cast<const SetStmt*>(stmt);
      return assignTarget(site, s->target, eval(ex, site, s->value), s->toplevel);
    }
    case StmtKind::SetBlock:
      return execSetBlock(ex, site, *static_cast<const SetBlockStmt*>(stmt));
    case StmtKind::FilterBlock:
      return execFilterBlock(ex, site, *static_cast<const FilterBlockStmt*>(stmt));
    case StmtKind::With:
      return execWith(ex, site, *static_cast<const WithStmt*>(stmt));
    case StmtKind::Do:
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
      case SlotInitKind::Parameter:
        break;
      case SlotInitKind::Resolve:
        frame.local(init.slot) = frame.context().resolve(init.name, init.hash, registry);
        break;
      case SlotInitKind::Alias:
        frame.local(init.slot) = frame.slot(init.alias);
        break;
      case SlotInitKind::Undefined:
        frame.local(init.slot) = Value::missing(init.name);
        break;
    }
  }
}

void assignTarget(Site& site, const Expr* target, const Value& value, bool toplevel) {
  switch (target->kind) {
    case ExprKind::Name:
      return storeName(site, static_cast<const NameExpr*>(target), value, toplevel);
    case ExprKind::Tuple: {
      const auto& items = static_cast<const SeqExpr*>(target)->items;
      std::vector<Value> values = unpack(value, items.size());
      for (size_t i = 0; i < items.size(); ++i) assignTarget(site, items[i], values[i], toplevel);
      return;
    }
    case ExprKind::NamespaceRef: {
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
  if (target->kind == ExprKind::Name) {
    auto* n = static_cast<const NameExpr*>(target);
    (slots ? frame.local(*slots) : frame.slot(n->ref)) = value;
    return;
  }
  const auto& items = static_cast<const SeqExpr*>(target)->items;
  // A list or tuple of the right size (the pairs of `items()`) is bound in place.
  bool in_place = value.isListOrTuple() && value.list().items().size() == items.size();
  std::vector<Value> copied = in_place ? std::vector<Value>() : unpack(value, items.size());
  const std::vector<Value>& values = in_place ? value.list().items() : copied;
  size_t offset = 0;
  for (size_t i = 0; i < items.size(); ++i) {
    bindTarget(frame, items[i], values[i], slots ? slots + offset : nullptr);
    if (slots) offset += countTargetNames(items[i]);
  }
}

}  // namespace smachac::tmpl
