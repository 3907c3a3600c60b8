// Scope analysis: decides, like Jinja2's compiler (idtracking), which variables each frame owns
// and how they are initialised (parameter, resolved from the context, copied from an outer
// frame, or unbound), then resolves every name to a frame slot. This reproduces Jinja's
// static scoping: e.g. `set` inside a `for` does not leak out, and a macro sees later
// top-level assignments of its template.
#pragma once

#include "backends/tmpl/ast/ast.h"
#include "backends/tmpl/parser/parser.h"

namespace smachac::tmpl {

/// Fills slot references, frame layouts and top-level flags; raises SyntaxFault for scoping
/// errors (e.g. `extends` inside a loop).
/// A deferred macro (parser.h) is left as it is; what its body will see of the root scope is
/// kept in `parsed.deferred`.
void analyzeScopes(ParsedTemplate& parsed, FrameLayout& root_frame);

/// Analyses a deferred macro once its body is parsed, as analyzeScopes would have.
void analyzeDeferredMacro(const DeferredMacro& deferred);

}  // namespace smachac::tmpl
