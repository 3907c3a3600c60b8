// The `dot` target: the state graph for Graphviz (`smachac -target=dot x.yml | dot -Tsvg`).
// Containers are clusters, transitions are edges labelled with outcomes (Concurrence
// outcome-map conditions dashed), container outcomes are terminal nodes, and states that
// diagnostics point into are drawn in red. Rendered by templates/dot/Graph.tpl.dot (`-I`
// overrides it); the filter `dotstr` quotes a string for the DOT language.
#pragma once

#include <optional>
#include <vector>

#include "backends/targets.h"

namespace smachac::backends::dot {

std::optional<std::vector<OutputFile>> emitDot(ir::Module&& module, EmitContext& context);

}  // namespace smachac::backends::dot
