// Lengauer–Tarjan dominators ("A fast algorithm for finding dominators in a flowgraph", 1979),
// simple version: semidominators in reverse DFS order with a path-compressed forest.
// Everything is indexed by DFS number; recursion (DFS, compress) is replaced by explicit
// stacks.
#include "passes/analysis/dominators.h"

#include <utility>

namespace smachac::passes {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

class LengauerTarjan {
 public:
  LengauerTarjan(const ContainerGraph& graph, const ContainerGraph& preds)
      : graph_(graph), preds_(preds), number_(graph.size(), kNone) {}

  std::vector<uint32_t> run() {
    std::vector<uint32_t> idom_of_node(graph_.size(), kNoDominator);
    if (graph_.size() == 0) return idom_of_node;
    numberNodes();
    size_t n = vertex_.size();
    semi_.resize(n);
    label_.resize(n);
    ancestor_.assign(n, kNone);
    idom_.assign(n, 0);
    for (uint32_t i = 0; i < n; ++i) semi_[i] = label_[i] = i;
    computeSemidominators();
    for (uint32_t w = 1; w < n; ++w) {
      if (idom_[w] != semi_[w]) idom_[w] = idom_[idom_[w]];
      idom_of_node[vertex_[w]] = vertex_[idom_[w]];
    }
    return idom_of_node;
  }

 private:
  /// Depth-first numbering from node 0: number_ (node -> DFS number), vertex_ (the inverse),
  /// parent_ (DFS tree parent, as a DFS number).
  void numberNodes() {
    std::vector<std::pair<uint32_t, uint32_t>> stack{{0, kNone}};  // (node, parent number)
    while (!stack.empty()) {
      auto [node, parent] = stack.back();
      stack.pop_back();
      if (number_[node] != kNone) continue;
      number_[node] = static_cast<uint32_t>(vertex_.size());
      vertex_.push_back(node);
      parent_.push_back(parent);
      std::span<const uint32_t> next = graph_.successors(node);
      for (auto it = next.rbegin(); it != next.rend(); ++it) {
        if (number_[*it] == kNone) stack.emplace_back(*it, number_[node]);
      }
    }
  }

  void computeSemidominators() {
    std::vector<std::vector<uint32_t>> bucket(vertex_.size());
    for (uint32_t w = static_cast<uint32_t>(vertex_.size()) - 1; w > 0; --w) {
      for (uint32_t pred : preds_.successors(vertex_[w])) {
        if (number_[pred] == kNone) continue;  // unreachable
        uint32_t u = eval(number_[pred]);
        if (semi_[u] < semi_[w]) semi_[w] = semi_[u];
      }
      bucket[semi_[w]].push_back(w);
      uint32_t p = parent_[w];
      ancestor_[w] = p;  // link
      for (uint32_t v : bucket[p]) {
        uint32_t u = eval(v);
        idom_[v] = semi_[u] < semi_[v] ? u : p;
      }
      bucket[p].clear();
    }
  }

  uint32_t eval(uint32_t v) {
    if (ancestor_[v] == kNone) return v;
    compress(v);
    return label_[v];
  }

  /// Path compression towards the forest root, nearest-the-root first.
  void compress(uint32_t v) {
    std::vector<uint32_t>& path = scratch_;
    path.clear();
    for (uint32_t x = v; ancestor_[ancestor_[x]] != kNone; x = ancestor_[x]) path.push_back(x);
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      uint32_t x = *it;
      uint32_t a = ancestor_[x];
      if (semi_[label_[a]] < semi_[label_[x]]) label_[x] = label_[a];
      ancestor_[x] = ancestor_[a];
    }
  }

  const ContainerGraph& graph_;
  const ContainerGraph& preds_;
  std::vector<uint32_t> number_;
  std::vector<uint32_t> vertex_, parent_, semi_, label_, ancestor_, idom_;
  std::vector<uint32_t> scratch_;
};

}  // namespace

std::vector<uint32_t> immediateDominators(const ContainerGraph& graph,
                                          const ContainerGraph& preds) {
  return LengauerTarjan(graph, preds).run();
}

}  // namespace smachac::passes
