// Container transition graphs and the walks over them. Every walk is iterative (a container
// may hold 100k states in one chain) and linear in nodes plus edges.
#include "passes/analysis/container_graph.h"

#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "ir/support/suggest.h"
#include "passes/analysis/children.h"
#include "passes/analysis/outcomes.h"

namespace smachac::passes {

ChildIndex::ChildIndex(const ir::Module& module) : index_(module.stateCount(), 0) {
  for (ir::StateId id : module.preorder()) {
    const std::vector<ir::StateId>& children = module.state(id).children;
    for (uint32_t i = 0; i < children.size(); ++i) index_[children[i].index] = i;
  }
}

namespace {

/// Reads unresolved targets as their closest sibling or outcome (see the header).
class TypoRecovery {
 public:
  TypoRecovery(const ir::Module& module, const ir::State& container)
      : module_(module), container_(container) {}

  /// The sibling node `target` most likely means, or nullopt for an outcome or nothing.
  std::optional<uint32_t> sibling(std::string_view target) {
    if (names_.empty()) build();
    std::optional<std::string> match = closestMatch(target, names_);
    if (!match) return std::nullopt;
    auto it = nodes_.find(*match);
    if (it == nodes_.end()) return std::nullopt;
    return it->second;
  }

 private:
  void build() {
    names_ = childNames(module_, container_);
    for (uint32_t i = 0; i < names_.size(); ++i) nodes_.emplace(names_[i], i);
    for (const ir::Name& outcome : container_.outcomes) names_.push_back(outcome.text);
  }

  const ir::Module& module_;
  const ir::State& container_;
  std::vector<std::string> names_;                   ///< siblings, then outcomes
  std::unordered_map<std::string, uint32_t> nodes_;  ///< sibling name -> first node
};

}  // namespace

ContainerGraph buildContainerGraph(const ir::Module& module, ir::StateId container,
                                   const ChildIndex& index) {
  const ir::State& c = module.state(container);
  NameSet outcomes = nameSet(c.outcomes);
  TypoRecovery recovery(module, c);
  ContainerGraph g;
  g.nodes = c.children;
  g.edge_begin.reserve(g.nodes.size() + 1);
  g.exits.reserve(g.nodes.size());
  for (ir::StateId child : g.nodes) {
    const ir::State& s = module.state(child);
    bool exit = canEndContainer(s, outcomes);
    g.edge_begin.push_back(static_cast<uint32_t>(g.edges.size()));
    for (const ir::Transition& t : s.transitions) {
      if (t.target_kind == ir::TargetKind::Sibling) {
        g.edges.push_back(index.of(t.target_state));
      } else if (t.target_kind == ir::TargetKind::Unresolved) {
        std::optional<uint32_t> node = recovery.sibling(t.target.text);
        if (node) g.edges.push_back(*node);
        exit = exit || !node;
      }
    }
    g.exits.push_back(exit ? 1 : 0);
  }
  g.edge_begin.push_back(static_cast<uint32_t>(g.edges.size()));
  return g;
}

ContainerGraph reverseGraph(const ContainerGraph& graph) {
  ContainerGraph r;
  r.nodes = graph.nodes;
  r.exits = graph.exits;
  r.edge_begin.assign(graph.size() + 1, 0);
  for (uint32_t target : graph.edges) ++r.edge_begin[target + 1];
  for (uint32_t n = 0; n < graph.size(); ++n) r.edge_begin[n + 1] += r.edge_begin[n];
  r.edges.resize(graph.edges.size());
  std::vector<uint32_t> fill(r.edge_begin.begin(), r.edge_begin.end() - 1);
  for (uint32_t n = 0; n < graph.size(); ++n) {
    for (uint32_t target : graph.successors(n)) r.edges[fill[target]++] = n;
  }
  return r;
}

std::vector<uint8_t> reachableFrom(const ContainerGraph& graph, std::span<const uint32_t> sources) {
  std::vector<uint8_t> seen(graph.size(), 0);
  std::vector<uint32_t> stack;
  auto visit = [&](uint32_t n) {
    if (seen[n]) return;
    seen[n] = 1;
    stack.push_back(n);
  };
  for (uint32_t source : sources) visit(source);
  while (!stack.empty()) {
    uint32_t n = stack.back();
    stack.pop_back();
    for (uint32_t next : graph.successors(n)) visit(next);
  }
  return seen;
}

std::vector<uint8_t> reachableFromStart(const ContainerGraph& graph) {
  if (graph.size() == 0) return {};
  uint32_t start = 0;
  return reachableFrom(graph, {&start, 1});
}

std::vector<uint8_t> canReachExit(const ContainerGraph& graph) {
  std::vector<uint32_t> exits;
  for (uint32_t n = 0; n < graph.size(); ++n) {
    if (graph.exits[n]) exits.push_back(n);
  }
  return reachableFrom(reverseGraph(graph), exits);
}

std::vector<uint32_t> reversePostorder(const ContainerGraph& graph) {
  std::vector<uint32_t> postorder;
  if (graph.size() == 0) return postorder;
  std::vector<uint8_t> seen(graph.size(), 0);
  // (node, index of the next successor to visit)
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0, 0}};
  seen[0] = 1;
  while (!stack.empty()) {
    auto& [node, next] = stack.back();
    std::span<const uint32_t> successors = graph.successors(node);
    if (next == successors.size()) {
      postorder.push_back(node);
      stack.pop_back();
      continue;
    }
    uint32_t target = successors[next++];
    if (!seen[target]) {
      seen[target] = 1;
      stack.emplace_back(target, 0);
    }
  }
  return {postorder.rbegin(), postorder.rend()};
}

}  // namespace smachac::passes
