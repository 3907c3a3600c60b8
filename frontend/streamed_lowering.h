// Lowering the main script's states while the fast YAML reader is still reading the rest
// (FrontendOptions::stream_states), so that a big script's whole YAML tree never exists.
// The result is exactly what reading first and lowering after gives, or nothing (and then the
// caller lowers that way). Internal to the frontend.
#pragma once

#include <optional>

#include "frontend/lower.h"

namespace smachac::frontend {

/// The streamed attempt at a script (the reader's states lowered as they come): true in `done` when
/// its result is the script's; otherwise nothing of it remains (diagnostics taken back).
std::optional<ir::Module> lowerStreamed(uint32_t file, const FrontendOptions& options,
                                        SourceManager& sources, DiagnosticEmitter& diags,
                                        bool& done);

}  // namespace smachac::frontend
