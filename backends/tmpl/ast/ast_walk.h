// Generic traversal of the AST in Jinja2's field order (used by the scope analysis).
#pragma once

#include <functional>

#include "backends/tmpl/ast/ast.h"

namespace smachac::tmpl {

/// Calls `fn` on the direct sub-expressions of `expr`, in evaluation order.
void forEachChild(const Expr* expr, const std::function<void(Expr*)>& fn);

/// Visits a statement's expressions and nested bodies in Jinja's field order.
struct StmtVisitor {
  std::function<void(Expr*)> expr;
  std::function<void(const Body&)> body;
};
void forEachPart(const Stmt* stmt, const StmtVisitor& visitor);

}  // namespace smachac::tmpl
