// Lint-time checks of states against their templates, for targets that render templates
// (smach, flexbe, cpp), run after the passes by `smachac lint`, `-fsyntax-only` and compiles:
//   * the template exists on the target's path (-I dirs, then the built-in sets)
//     [unknown-template, with "did you mean"];
//   * every variable the template's meta block requires is given, and one of each group of
//     alternatives [missing-template-variable];
//   * every other key of the state is a variable the meta block declares
//     [unknown-template-variable, warning, with "did you mean"];
//   * literal values have a declared type (str, int, float, bool, list…, dict…)
//     [template-variable-type, warning];
//   * for the smach target, what its SMACHA-compatible output does differently from C++
//     (smach/smach_lint.h) [smach-*, warnings].
// Templates without a meta block, and types the checker does not know (message classes,
// functions), are not checked.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"

namespace smachac::backends {

/// Returns false when an error was reported.
bool checkTemplates(const ir::Module& module, std::string_view target,
                    const std::vector<std::string>& template_dirs, DiagnosticEmitter& diags);

}  // namespace smachac::backends
