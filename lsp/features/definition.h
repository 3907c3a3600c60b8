// textDocument/definition, and the Locations of the navigation features. Definition leads
// from a name to what declares it: a transition target to the sibling state or to the
// container outcome it leaves by (the script's outcomes at the root); a transition key,
// `default_outcome` or outcome_map entry to the outcome's declaration; an outcome_map
// condition to the child state and its outcome; a userdata key to where its value comes from
// (script_index.h: `userdata` entries and the output keys of leaves, through remapping and
// container interfaces); a lookup to its `params` entry; `script:` to the start of the
// sub-script file; `template:` to the template's file (a built-in one's read-only cache copy,
// lsp/index_templates.h). Nothing there, or nothing declares it: null.
#pragma once

#include <memory>
#include <vector>

#include "lsp/analysis.h"
#include "lsp/json_rpc.h"
#include "lsp/script_index.h"
#include "lsp/workspace.h"

namespace smachac::lsp {

/// The Location of `loc`, a span in a file of `analysis`.
Json locationJson(const Analysis& analysis, const SourceLoc& loc);

/// The Locations of `occurrences`, in order, each once.
Json locationsJson(const Analysis& analysis, const std::vector<const Occurrence*>& occurrences);

/// A Location at the start of the file `uri`.
Json fileStartJson(const std::string& uri);

/// What a navigation request (`textDocument`, `position`) points at: the index of its
/// document and the occurrence there. Both null when the document is not open or nothing is
/// there.
struct PointedAt {
  std::unique_ptr<ScriptIndex> index;
  const Occurrence* occurrence = nullptr;
};
PointedAt pointedAt(Workspace& workspace, const Json& params);

}  // namespace smachac::lsp
