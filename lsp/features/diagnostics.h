// textDocument/publishDiagnostics for one analysis: the command line's diagnostics, same
// kinds (as `code`), messages and severities. Notes become relatedInformation (a note
// without a location is appended to the message). A diagnostic located in a sub-script is
// shown where the document includes it, as "in <file>: message", with the sub-script
// location as related information.
#pragma once

#include "lsp/analysis.h"
#include "lsp/json_rpc.h"

namespace smachac::lsp {

/// The params of a publishDiagnostics notification.
Json publishDiagnosticsParams(const Analysis& analysis);

/// One diagnostic of the analysis as publishDiagnostics shows it (code actions name the
/// diagnostics they fix with it).
Json diagnosticJson(const Analysis& analysis, const Diagnostic& diagnostic);

}  // namespace smachac::lsp
