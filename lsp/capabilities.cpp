// ServerCapabilities: one entry per feature of requests.def, and the document sync.
#include "lsp/capabilities.h"

#include "ir/support/version.h"

namespace smachac::lsp {

Json initializeResult() {
  Json capabilities = {
      {"positionEncoding", "utf-16"},
      {"textDocumentSync",
       {{"openClose", true}, {"change", 2}, {"save", {{"includeText", false}}}}},
  };
  return {{"capabilities", capabilities},
          {"serverInfo", {{"name", "smachac"}, {"version", std::string(kVersion)}}}};
}

}  // namespace smachac::lsp
