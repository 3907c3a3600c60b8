// The renderer's internal interface: evaluating expressions, executing statements, calling
// values, and running templates, blocks and modules (render_*.cpp, loop.cpp, methods.cpp).
#pragma once

#include <string>

#include "backends/tmpl/renderer/call_args.h"
#include "backends/tmpl/renderer/runtime.h"

namespace smachac::tmpl {

// render_expr.cpp
/// Any expression (locates a fault at the expression); eval below is this with the two
/// commonest kinds inline.
Value evalExpr(Exec& ex, Site& site, const Expr* expr);
/// Evaluates `expr`: a constant or a name (neither can fail) inline, the rest by evalExpr.
inline Value eval(Exec& ex, Site& site, const Expr* expr) {
  if (expr->kind == ExprKind::Name) {
    return site.frame->slot(static_cast<const NameExpr*>(expr)->ref).loaded();
  }
  if (expr->kind == ExprKind::Const) return static_cast<const ConstExpr*>(expr)->value;
  return evalExpr(ex, site, expr);
}
void evalArgs(Exec& ex, Site& site, const ArgList& list, OwnedArgs& out);
/// Jinja's environment.getattr: attribute (method) first, then item.
Value getAttribute(const Value& obj, const std::string* name);
/// Jinja's environment.getitem: item first, then attribute.
Value getItem(const Value& obj, const Value& key);
Value callValue(Exec& ex, const Value& fn, const CallArgs& args);
Value applyFilterExpr(Exec& ex, Site& site, const FilterExpr* filter, const Value* block_input);

// render_stmt.cpp
void execBody(Exec& ex, Site& site, const Body& body);
void initFrame(Frame& frame, const FrameLayout& layout, const Registry& registry);
void assignTarget(Site& site, const Expr* target, const Value& value, bool toplevel);
/// Binds a loop or `with` target (a name or a tuple of names) in `frame`.
void bindTarget(Frame& frame, const Expr* target, const Value& value, const uint16_t* slots);

// render_template.cpp
Ref<Context> newContext(Exec& ex, const Template& tmpl, Value parent);
void registerBlocks(Exec& ex, Context& ctx, const Template& tmpl);
void renderRoot(Exec& ex, const Template& tmpl, Context& ctx, std::string& out);
/// The root code of `tmpl` under this call's skip policy (RootPlan).
const Body& rootBody(Exec& ex, const Template& tmpl);
void renderBlockAt(Exec& ex, Context& ctx, size_t index, std::string& out);
/// Runs `tmpl` in `ctx` (a fresh context) and collects its exports.
Value makeModule(Exec& ex, const Template& tmpl, Ref<Context> ctx);
Value defaultModule(Exec& ex, const Template& tmpl);
const Template& loadTemplate(Exec& ex, const Value& name);

// loop.cpp
void execFor(Exec& ex, Site& site, const ForStmt& node);

// globals.cpp
/// Sets an attribute of a `namespace()` object; false if `ns` is not one.
bool setNamespaceAttribute(const Value& ns, const std::string& name, const Value& value);

// methods.cpp
bool hasMethod(const Value& self, std::string_view name);
bool callMethod(Exec& ex, const Value& self, std::string_view name, const CallArgs& args,
                Value& out);

}  // namespace smachac::tmpl
