// Dominators of a container graph: node d dominates n when every path from the initial state
// (node 0) to n passes through d. Computed with the Lengauer–Tarjan algorithm (path
// compression, O(E log N)), iteratively, so chains of 100k states are fine.
#pragma once

#include <cstdint>
#include <vector>

#include "passes/analysis/container_graph.h"

namespace smachac::passes {

inline constexpr uint32_t kNoDominator = UINT32_MAX;

/// The immediate dominator of every node reachable from node 0; kNoDominator for node 0 and
/// for unreachable nodes. `preds` is reverseGraph(graph).
std::vector<uint32_t> immediateDominators(const ContainerGraph& graph, const ContainerGraph& preds);

}  // namespace smachac::passes
