// "included from here": where each sub-script is included, and the notes that say so on the
// diagnostics located in a sub-script. A sub-script included twice is lowered and checked
// twice; its diagnostics are kept once, with a note for each place that includes it.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_loc.h"

namespace smachac::frontend {

/// Sub-script file id → the `script:` values that include it, in order of inclusion.
using IncludeSites = std::map<uint32_t, std::vector<SourceLoc>>;

/// From diagnostic index `first` on: gives each diagnostic located in a sub-script one
/// "included from here" note per place that includes it, and drops the later ones of the
/// diagnostics that repeat there (same kind and location).
void noteInclusions(DiagnosticEmitter& diags, size_t first, const IncludeSites& sites);

}  // namespace smachac::frontend
