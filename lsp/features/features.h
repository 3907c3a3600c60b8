// The request handlers of the features, one topic per file (requests.def lists them).
// Each takes the request's params and returns its result; a malformed params object throws
// nlohmann::json::exception (the server answers InvalidParams).
#pragma once

#include "lsp/json_rpc.h"
#include "lsp/workspace.h"

namespace smachac::lsp {

/// textDocument/codeAction (code_actions.cpp).
Json codeAction(Workspace& workspace, const Json& params);

/// textDocument/definition (definition.cpp).
Json definition(Workspace& workspace, const Json& params);

/// textDocument/references (references.cpp).
Json references(Workspace& workspace, const Json& params);

/// textDocument/hover (hover.cpp).
Json hover(Workspace& workspace, const Json& params);

/// textDocument/semanticTokens/full (semantic_tokens.cpp).
Json semanticTokensFull(Workspace& workspace, const Json& params);

/// textDocument/completion (completion.cpp).
Json completion(Workspace& workspace, const Json& params);

/// textDocument/documentSymbol (symbols.cpp).
Json documentSymbol(Workspace& workspace, const Json& params);

/// textDocument/foldingRange (folding.cpp).
Json foldingRange(Workspace& workspace, const Json& params);

}  // namespace smachac::lsp
