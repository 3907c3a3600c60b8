// Lint warnings for scripts whose SMACH output behaves differently from their C++ output
// because the SMACH target keeps SMACHA's behaviour on purpose (reference: SMACHA's
// templates and generator; stdlib/runtime/README.md, "SMACH output and C++"):
//   * userdata keys are lower-cased where they are set [smach-lowercased-userdata-key];
//   * string values that look like numbers, dotted names or calls are written as Python
//     code [smach-string-as-code];
//   * a RandomOutcomeState without `callbacks` leaves its default callback set for the
//     states after it in its container (a template global) [smach-leaked-callbacks];
//   * maps keep the script's key order in Python, the C++ runtime sorts them
//     [smach-map-order].
// Run by checkTemplates for the smach target (compiles, `smachac lint`, -fsyntax-only).
#pragma once

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"

namespace smachac::backends::smach {

void checkSmachDivergences(const ir::Module& module, DiagnosticEmitter& diags);

}  // namespace smachac::backends::smach
