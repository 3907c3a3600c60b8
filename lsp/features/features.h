// The request handlers of the features, one topic per file (requests.def lists them).
// Each takes the request's params and returns its result; a malformed params object throws
// nlohmann::json::exception (the server answers InvalidParams).
#pragma once

#include "lsp/json_rpc.h"
#include "lsp/workspace.h"

namespace smachac::lsp {}  // namespace smachac::lsp
