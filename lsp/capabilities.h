// The server's answer to `initialize`: what it can do, and its name and version.
#pragma once

#include "lsp/json_rpc.h"

namespace smachac::lsp {

Json initializeResult();

}  // namespace smachac::lsp
