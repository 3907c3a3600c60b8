// textDocument/semanticTokens/full: one token per name of the document the script index
// knows, in text order, none overlapping, none spanning lines, in the protocol's relative
// encoding (line and start deltas, length in UTF-16 units, type, modifier bits). Token types
// by what the name is: a state `class`, an outcome `enumMember`, a userdata key `variable`, a
// template `type`, a sub-script `namespace`, a param `parameter`; modifiers `declaration`
// (where it is declared or set) and `readonly` (params, which states cannot change).
#pragma once

#include "lsp/json_rpc.h"

namespace smachac::lsp {

/// The legend announced in the capabilities.
Json semanticTokensLegend();

}  // namespace smachac::lsp
