// Generic traversal of the AST in Jinja2's field order (used by the scope analysis). The
// callbacks are passed as `Visit`, a reference to a callable that lives at least as long as the
// call it is given to: binding a lambda to it copies and allocates nothing (std::function did
// both for every sub-expression the analysis entered, a lambda capturing three references
// being too large for its inline buffer).
#pragma once

#include <memory>
#include <type_traits>
#include <utility>

#include "backends/tmpl/ast/ast.h"

namespace smachac::tmpl {

template <class Signature>
class Visit;

/// A non-owning reference to a callable taking `Args...`.
template <class... Args>
class Visit<void(Args...)> {
 public:
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, Visit> && std::is_invocable_v<F&, Args...>)
      Visit(F&& fn)  // NOLINT(google-explicit-constructor): binds lambdas at call sites
      : target_(const_cast<void*>(static_cast<const void*>(std::addressof(fn)))),
        call_([](void* target, Args... args) {
          (*static_cast<std::remove_reference_t<F>*>(target))(std::forward<Args>(args)...);
        }) {}

  void operator()(Args... args) const { call_(target_, std::forward<Args>(args)...); }

 private:
  void* target_;
  void (*call_)(void*, Args...);
};

/// Calls `fn` on the direct sub-expressions of `expr`, in evaluation order.
void forEachChild(const Expr* expr, Visit<void(Expr*)> fn);

/// Visits a statement's expressions and nested bodies in Jinja's field order.
struct StmtVisitor {
  Visit<void(Expr*)> expr;
  Visit<void(const Body&)> body;
};
void forEachPart(const Stmt* stmt, const StmtVisitor& visitor);

}  // namespace smachac::tmpl
