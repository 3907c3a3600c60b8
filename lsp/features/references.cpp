// textDocument/references: every occurrence of the symbol under the position, in the
// document (in text order) and in its sub-scripts; declarations (a state's name, an outcome's
// `outcomes` entry, a key's `userdata` entries and leaves' output keys, a `params` entry)
// only when the context asks for them. Nothing there: null.
#include "lsp/features/definition.h"
#include "lsp/features/features.h"

namespace smachac::lsp {

Json references(Workspace& workspace, const Json& params) {
  PointedAt at = pointedAt(workspace, params);
  if (!at.occurrence) return nullptr;
  const Json& context = params.contains("context") ? params["context"] : Json::object();
  bool declarations = context.value("includeDeclaration", false);
  std::vector<const Occurrence*> found;
  for (const Occurrence* each : at.index->occurrences(at.occurrence->symbol)) {
    if (declarations || each->role != Role::Definition) found.push_back(each);
  }
  return locationsJson(at.index->analysis(), found);
}

}  // namespace smachac::lsp
