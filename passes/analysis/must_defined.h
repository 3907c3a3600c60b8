// Definite assignment of userdata keys over a sequential container: a key is defined when a
// state starts if, on every path from the initial state to it, the key is defined initially
// (passes/analysis/userdata_scope.h) or written by an earlier state.
//
// A forward dataflow problem: OUT(s) = IN(s) ∪ writes(s), IN(s) = ∩ OUT(p) over the reachable
// predecessors p, IN(initial) = the initially defined keys. Most reads are settled without
// it, in one linear walk over the dominator tree (dominators.h): a key defined initially, or
// written by a state that dominates the reader, is defined. The keys of the other reads
// ("tracked" keys: written by some child, never by a dominator of the reader) live in bit sets
// per state, solved with a worklist in reverse post-order. Tracked keys are processed in
// chunks so that a chunk's bit sets stay under a fixed memory budget: the cost is linear for a
// bounded number of tracked keys per container, and (tracked keys / 64) words per state and
// edge beyond that.
#pragma once

#include <cstdint>
#include <vector>

#include "passes/analysis/container_graph.h"
#include "passes/analysis/userdata_scope.h"

namespace smachac::passes {

/// A read by a child (a node of the graph) that some path reaches while its key is undefined.
struct UndefinedRead {
  uint32_t child = 0;
  const KeyUse* use = nullptr;
};

/// Children's reads whose key is not defined on every path from the initial state, sorted by
/// child and then read. Reads of keys no child writes are not reported here (they are
/// undefined on every path), nor are reads in states unreachable from the initial state, nor
/// the container's output keys.
/// The default memory budget of one chunk's bit sets, in 64-bit words (8 MiB).
inline constexpr size_t kDefaultBudgetWords = size_t{1} << 20;

std::vector<UndefinedRead> findMaybeUndefinedReads(const ContainerGraph& graph,
                                                   const UserdataScope& scope,
                                                   size_t budget_words = kDefaultBudgetWords);

}  // namespace smachac::passes
