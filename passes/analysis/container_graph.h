// The transition graph of one sequential container (StateMachine or the root). Nodes are the
// container's children in order, node 0 being the initial state (SMACH starts with the first
// state added); edges are transitions to siblings; a node is an exit when the child can end
// the container (passes/analysis/outcomes.h). Edges are stored compactly (CSR) so the graph of
// a container with 100k states costs a few arrays.
//
// An unresolved target (an error reported by check-transitions) is read as the name the
// error suggests, like a compiler recovering from a typo: an edge to the sibling, or an exit
// for an outcome; with no suggestion, an exit. Later analyses then do not pile up warnings
// that fixing the typo would remove.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ir/module.h"

namespace smachac::passes {

/// The position of every state among its parent's children, for turning a transition's
/// target into a node number. Built once per pass, in time linear in the module.
class ChildIndex {
 public:
  explicit ChildIndex(const ir::Module& module);
  uint32_t of(ir::StateId id) const { return index_[id.index]; }

 private:
  std::vector<uint32_t> index_;
};

struct ContainerGraph {
  std::vector<ir::StateId> nodes;
  std::vector<uint32_t> edge_begin;  ///< edges of node n: edges[edge_begin[n], edge_begin[n+1])
  std::vector<uint32_t> edges;
  std::vector<uint8_t> exits;

  uint32_t size() const { return static_cast<uint32_t>(nodes.size()); }
  std::span<const uint32_t> successors(uint32_t node) const {
    return {edges.data() + edge_begin[node], edges.data() + edge_begin[node + 1]};
  }
};

ContainerGraph buildContainerGraph(const ir::Module& module, ir::StateId container,
                                   const ChildIndex& index);

/// The same nodes with every edge reversed (exits are kept).
ContainerGraph reverseGraph(const ContainerGraph& graph);

/// Marks the nodes reachable from `sources` (a breadth-first search).
std::vector<uint8_t> reachableFrom(const ContainerGraph& graph, std::span<const uint32_t> sources);

/// Nodes reachable from the initial state (node 0); empty graphs have none.
std::vector<uint8_t> reachableFromStart(const ContainerGraph& graph);

/// Nodes from which some exit can be reached.
std::vector<uint8_t> canReachExit(const ContainerGraph& graph);

/// The nodes reachable from node 0, in reverse post-order of a depth-first search.
std::vector<uint32_t> reversePostorder(const ContainerGraph& graph);

}  // namespace smachac::passes
