// ServerCapabilities: one entry per feature of requests.def, and the document sync.
#include "lsp/capabilities.h"

#include "ir/support/version.h"
#include "lsp/features/semantic_tokens.h"

namespace smachac::lsp {

Json initializeResult() {
  Json capabilities = {
      {"positionEncoding", "utf-16"},
      {"textDocumentSync",
       {{"openClose", true}, {"change", 2}, {"save", {{"includeText", false}}}}},
      {"definitionProvider", true},
      {"referencesProvider", true},
      {"hoverProvider", true},
      {"semanticTokensProvider", {{"legend", semanticTokensLegend()}, {"full", true}}},
      {"completionProvider",
       {{"triggerCharacters", {":", " ", "[", "{", ","}}, {"resolveProvider", false}}},
      {"documentSymbolProvider", true},
      {"foldingRangeProvider", true},
      {"codeActionProvider",
       {{"codeActionKinds", {"quickfix", "refactor.rewrite", "refactor.extract"}}}},
  };
  return {{"capabilities", capabilities},
          {"serverInfo", {{"name", "smachac"}, {"version", std::string(kVersion)}}}};
}

}  // namespace smachac::lsp
