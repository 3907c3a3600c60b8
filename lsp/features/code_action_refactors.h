// The refactorings of textDocument/codeAction: SMACHA's contain and extract on the
// document's unsaved text (refactor/contain.h and refactor/extract.h have their rules).
//   * contain (refactor.rewrite): a non-empty selection that touches a run of consecutive
//     root states gives two actions, "contain them in a new StateMachine" and "... in a new
//     Concurrence"; the container is named CONTAINER, else CONTAINER_2, ... (a name no
//     state and no outcome of the script has)
//   * extract (refactor.extract): the cursor or selection within a root state's name gives
//     "extract it into a sub-script": the sub-script is created next to the document, named
//     after the state in lower case (`foo.yml`, else `foo_2.yml`, ...: a name no file there
//     and no open document has, with or without `.yml`), and the document includes it as
//     `script: foo`. It needs a file document, a state name that can be a file name
//     (letters, digits, `_`, `-`) and a client that can create files.
// An action is offered only when its refactoring succeeds, on a script that lowers without
// errors; the document's own sub-scripts are read as the editor has them.
#pragma once

#include <vector>

#include "lsp/features/code_action.h"

namespace smachac::lsp {

struct RefactorKinds {
  bool contain = false;
  bool extract = false;
};

std::vector<Json> refactorActions(const ActionRequest& request, RefactorKinds kinds);

}  // namespace smachac::lsp
