// The must-defined dataflow solver, one chunk of tracked keys at a time.
#include "passes/analysis/must_defined.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <span>
#include <utility>

#include "passes/analysis/dominators.h"

namespace smachac::passes {
namespace {

using Word = uint64_t;
constexpr uint32_t kNone = UINT32_MAX;

/// What every chunk shares: the graph, its reverse and the visiting order.
struct Problem {
  const ContainerGraph& graph;
  const UserdataScope& scope;
  ContainerGraph preds;
  std::vector<uint32_t> rpo;
  std::vector<uint32_t> rpo_index;  ///< kNone for unreachable nodes

  Problem(const ContainerGraph& g, const UserdataScope& s)
      : graph(g),
        scope(s),
        preds(reverseGraph(g)),
        rpo(reversePostorder(g)),
        rpo_index(g.size(), kNone) {
    for (uint32_t i = 0; i < rpo.size(); ++i) rpo_index[rpo[i]] = i;
  }
  bool reachable(uint32_t node) const { return rpo_index[node] != kNone; }
};

/// The dominator tree of the reachable nodes, children in CSR form.
ContainerGraph dominatorTree(const Problem& p) {
  std::vector<uint32_t> idom = immediateDominators(p.graph, p.preds);
  ContainerGraph tree;
  tree.edge_begin.assign(p.graph.size() + 1, 0);
  for (uint32_t parent : idom) {
    if (parent != kNoDominator) ++tree.edge_begin[parent + 1];
  }
  for (uint32_t n = 0; n < p.graph.size(); ++n) tree.edge_begin[n + 1] += tree.edge_begin[n];
  tree.edges.resize(tree.edge_begin.back());
  std::vector<uint32_t> fill(tree.edge_begin.begin(), tree.edge_begin.end() - 1);
  for (uint32_t n = 0; n < p.graph.size(); ++n) {
    if (idom[n] != kNoDominator) tree.edges[fill[idom[n]]++] = n;
  }
  tree.nodes = p.graph.nodes;
  return tree;
}

/// Reads that dominance does not settle. A read needs the solver when its key is written by
/// some child and not defined initially, and no strict dominator of the reader writes it: a
/// write by a dominator happens on every path to the reader. One walk over the dominator tree
/// that counts, per key, the writers among the current node's ancestors: linear.
std::vector<UndefinedRead> undecidedReads(const Problem& p) {
  std::vector<UndefinedRead> undecided;
  ContainerGraph tree = dominatorTree(p);
  std::vector<uint32_t> writers(p.scope.keyCount(), 0);
  auto count = [&](uint32_t node, int delta) {
    for (const KeyUse& use : p.scope.writes(node)) writers[use.key] += delta;
  };
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0, 0}};  // (node, next child)
  for (const KeyUse& use : p.scope.reads(0)) {
    if (p.scope.written(use.key) && !p.scope.initiallyDefined(use.key))
      undecided.push_back({0, &use});
  }
  count(0, 1);
  while (!stack.empty()) {
    auto& [node, next] = stack.back();
    std::span<const uint32_t> children = tree.successors(node);
    if (next == children.size()) {
      count(node, -1);
      stack.pop_back();
      continue;
    }
    uint32_t child = children[next++];
    for (const KeyUse& use : p.scope.reads(child)) {
      bool decided = writers[use.key] > 0 || p.scope.initiallyDefined(use.key);
      if (!decided && p.scope.written(use.key)) undecided.push_back({child, &use});
    }
    count(child, 1);
    stack.emplace_back(child, 0);
  }
  std::sort(undecided.begin(), undecided.end(),
            [](const UndefinedRead& a, const UndefinedRead& b) { return a.child < b.child; });
  return undecided;
}

/// The distinct keys of `reads`, in first-read order.
std::vector<uint32_t> keysOf(const std::vector<UndefinedRead>& reads, uint32_t key_count) {
  std::vector<uint8_t> seen(key_count, 0);
  std::vector<uint32_t> keys;
  for (const UndefinedRead& read : reads) {
    if (!seen[read.use->key]) seen[read.use->key] = 1, keys.push_back(read.use->key);
  }
  return keys;
}

/// The bit sets of one chunk of tracked keys: bit b stands for keys[b].
class Chunk {
 public:
  Chunk(const Problem& problem, std::span<const uint32_t> keys)
      : p_(problem),
        words_((keys.size() + 63) / 64),
        bit_(p_.scope.keyCount(), kNone),
        out_(p_.graph.size() * words_, ~Word{0}) {
    for (uint32_t b = 0; b < keys.size(); ++b) bit_[keys[b]] = b;
  }

  void solve() {
    std::priority_queue<uint32_t, std::vector<uint32_t>, std::greater<>> work;
    std::vector<uint8_t> queued(p_.graph.size(), 0);
    auto enqueue = [&](uint32_t node) {
      if (queued[node]) return;
      queued[node] = 1;
      work.push(p_.rpo_index[node]);
    };
    for (uint32_t node : p_.rpo) enqueue(node);
    std::vector<Word> next(words_);
    while (!work.empty()) {
      uint32_t node = p_.rpo[work.top()];
      work.pop();
      queued[node] = 0;
      if (!transfer(node, next)) continue;
      for (uint32_t succ : p_.graph.successors(node)) enqueue(succ);
    }
  }

  /// Checks `reads` (sorted by node) against IN of their node.
  void collect(const std::vector<UndefinedRead>& reads, std::vector<UndefinedRead>& found) const {
    std::vector<Word> in(words_);
    uint32_t current = kNone;
    for (const UndefinedRead& read : reads) {
      uint32_t b = bit_[read.use->key];
      if (b == kNone) continue;
      if (read.child != current) meet(current = read.child, in);
      if (!((in[b / 64] >> (b % 64)) & 1)) found.push_back(read);
    }
  }

 private:
  Word* out(uint32_t node) { return out_.data() + size_t{node} * words_; }
  const Word* out(uint32_t node) const { return out_.data() + size_t{node} * words_; }

  /// IN(node): nothing tracked at the initial state, else the AND of reachable predecessors.
  void meet(uint32_t node, std::vector<Word>& in) const {
    std::fill(in.begin(), in.end(), node == 0 ? Word{0} : ~Word{0});
    if (node == 0) return;
    for (uint32_t pred : p_.preds.successors(node)) {
      if (!p_.reachable(pred)) continue;
      for (size_t w = 0; w < words_; ++w) in[w] &= out(pred)[w];
    }
  }

  /// Recomputes OUT(node); returns whether it changed.
  bool transfer(uint32_t node, std::vector<Word>& next) {
    meet(node, next);
    for (const KeyUse& use : p_.scope.writes(node)) {
      uint32_t b = bit_[use.key];
      if (b != kNone) next[b / 64] |= Word{1} << (b % 64);
    }
    if (std::equal(next.begin(), next.end(), out(node))) return false;
    std::copy(next.begin(), next.end(), out(node));
    return true;
  }

  const Problem& p_;
  size_t words_;
  std::vector<uint32_t> bit_;  ///< per scope key: its bit in this chunk, or kNone
  std::vector<Word> out_;
};

}  // namespace

std::vector<UndefinedRead> findMaybeUndefinedReads(const ContainerGraph& graph,
                                                   const UserdataScope& scope,
                                                   size_t budget_words) {
  std::vector<UndefinedRead> found;
  if (graph.size() == 0) return found;
  Problem problem(graph, scope);
  std::vector<UndefinedRead> undecided = undecidedReads(problem);
  std::vector<uint32_t> tracked = keysOf(undecided, scope.keyCount());
  if (tracked.empty()) return found;
  size_t words = std::max<size_t>(1, budget_words / graph.size());
  size_t chunk = std::min(tracked.size(), words * 64);
  for (size_t first = 0; first < tracked.size(); first += chunk) {
    size_t count = std::min(chunk, tracked.size() - first);
    Chunk bits(problem, std::span<const uint32_t>(tracked).subspan(first, count));
    bits.solve();
    bits.collect(undecided, found);
  }
  std::sort(found.begin(), found.end(), [](const UndefinedRead& a, const UndefinedRead& b) {
    return a.child != b.child ? a.child < b.child : std::less<const KeyUse*>()(a.use, b.use);
  });
  return found;
}

}  // namespace smachac::passes
