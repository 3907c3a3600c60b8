// The view model of `-target=dot`: the state tree as template values for templates/dot/.
//   graph  = {name, root: container, flagged_count}
//   state  = {id, name, template, kind, flagged, entry, exit?}          (a leaf)
//   container = state + {children: [state|container], outcomes: [{id, name, default}],
//                        edges: [{from, to, label, lhead, ltail, style}], placeholder?}
// Node ids are stable (from state ids). A container is entered at its first child (`entry`);
// its outcomes are terminal nodes inside its cluster; a state is `flagged` when a diagnostic
// (a warning: errors stop the compile) points into it.
#pragma once

#include <span>

#include "backends/tmpl/values/value.h"
#include "ir/module.h"
#include "ir/support/diagnostic.h"

namespace smachac::backends::dot {

tmpl::Value graphView(const ir::Module& module, std::span<const Diagnostic> diagnostics);

}  // namespace smachac::backends::dot
