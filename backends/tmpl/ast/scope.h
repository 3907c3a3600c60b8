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
void analyzeScopes(ParsedTemplate& parsed, FrameLayout& root_frame);

}  // namespace smachac::tmpl
