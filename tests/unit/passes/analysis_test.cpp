// passes/analysis: container graphs, userdata scopes, the must-defined solver, identifiers.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>
#include <string>

#include "ir/support/identifiers.h"
#include "passes/analysis/container_graph.h"
#include "passes/analysis/dominators.h"
#include "passes/analysis/must_defined.h"
#include "passes/analysis/userdata_scope.h"
#include "tests/unit/passes/compile.h"

namespace smachac::passes {
namespace {

using testing::find;
using testing::lower;

std::vector<uint32_t> successors(const ContainerGraph& g, uint32_t node) {
  auto s = g.successors(node);
  return {s.begin(), s.end()};
}

std::vector<int> flags(const std::vector<uint8_t>& v) { return {v.begin(), v.end()}; }

/// The names read while undefined, as "STATE:key".
std::vector<std::string> maybeUndefined(const testing::Compiled& c, size_t budget) {
  const ir::Module& m = *c.module;
  ContainerGraph graph = buildContainerGraph(m, m.root(), ChildIndex(m));
  UserdataScope scope(m, m.root());
  std::vector<std::string> found;
  for (const UndefinedRead& r : findMaybeUndefinedReads(graph, scope, budget)) {
    found.push_back(m.state(graph.nodes[r.child]).name.text + ":" + r.use->scope_name->text);
  }
  return found;
}

constexpr const char* kDiamond = R"(
name: d
template: Base
outcomes: [done]
states:
  - START: {template: T, outcomes: [a, b], transitions: {a: LEFT, b: RIGHT}}
  - LEFT: {template: T, outcomes: [ok], output_keys: [x, y], transitions: {ok: JOIN}}
  - RIGHT: {template: T, outcomes: [ok], output_keys: [y], transitions: {ok: JOIN}}
  - JOIN: {template: T, outcomes: [ok, again], input_keys: [x, y, z], transitions: {ok: done, again: LOOP}}
  - LOOP: {template: T, outcomes: [ok], output_keys: [z], transitions: {ok: JOIN}}
  - DEAD: {template: T, outcomes: [ok], input_keys: [x], transitions: {ok: JOIN}}
)";

TEST_CASE("a container graph has sibling edges, exits and the reachable set") {
  auto c = lower(kDiamond);
  const ir::Module& m = *c->module;
  ContainerGraph g = buildContainerGraph(m, m.root(), ChildIndex(m));
  REQUIRE(g.size() == 6);
  CHECK(successors(g, 0) == std::vector<uint32_t>{1, 2});
  CHECK(successors(g, 3) == std::vector<uint32_t>{4});
  CHECK(flags(g.exits) == std::vector<int>{0, 0, 0, 1, 0, 0});
  CHECK(flags(reachableFromStart(g)) == std::vector<int>{1, 1, 1, 1, 1, 0});
  CHECK(flags(canReachExit(g)) == std::vector<int>{1, 1, 1, 1, 1, 1});
  CHECK(successors(reverseGraph(g), 3) == std::vector<uint32_t>{1, 2, 4, 5});
  std::vector<uint32_t> rpo = reversePostorder(g);
  REQUIRE(rpo.size() == 5);
  CHECK(rpo.front() == 0);
  auto pos = [&](uint32_t n) { return std::find(rpo.begin(), rpo.end(), n) - rpo.begin(); };
  CHECK(pos(1) < pos(3));
  CHECK(pos(2) < pos(3));
}

TEST_CASE("an unresolved target is read as the name it most likely means") {
  auto c = lower(R"(
name: t
template: Base
outcomes: [done]
states:
  - A: {template: T, outcomes: [ok, bad], transitions: {ok: BB, bad: dne}}
  - BB: {template: T, outcomes: [ok], transitions: {ok: A}}
  - C: {template: T, outcomes: [ok], transitions: {ok: XYZZY}}
)");
  const ir::Module& m = *c->module;
  ContainerGraph g = buildContainerGraph(m, m.root(), ChildIndex(m));
  CHECK(successors(g, 0) == std::vector<uint32_t>{1});
  CHECK(g.exits[0] == 1);  // `dne` means the outcome `done`
  CHECK(g.exits[1] == 0);
  CHECK(g.exits[2] == 1);  // no suggestion: assumed to end the container
}

TEST_CASE("leaves with unknown outcomes may end their container") {
  auto c = lower(R"(
name: t
template: Base
outcomes: [done]
states:
  - A: {template: T, transitions: {ok: B}}
  - B: {template: T}
  - C: {template: T, outcomes: [done, other], transitions: {other: A}}
  - SUB:
      template: StateMachine
      outcomes: [done]
      states:
        - X: {template: T, outcomes: [a], transitions: {a: Y}}
        - Y: {template: T, outcomes: [done]}
)");
  const ir::Module& m = *c->module;
  ContainerGraph g = buildContainerGraph(m, m.root(), ChildIndex(m));
  CHECK(flags(g.exits) == std::vector<int>{1, 1, 1, 1});
  // with declared outcomes, only what is mapped to an outcome or passed through counts
  CHECK(flags(buildContainerGraph(m, find(m, "SUB"), ChildIndex(m)).exits) ==
        std::vector<int>{0, 1});
}

TEST_CASE("a scope holds the container's and its leaves' userdata, not child containers'") {
  auto c = lower(R"(
name: s
template: Base
outcomes: [done]
userdata: {a: 1}
states:
  - L: {template: T, userdata: {b: 2}, input_keys: [k], remapping: {k: a}, output_keys: [o],
        transitions: {ok: SUB}}
  - SUB:
      template: StateMachine
      outcomes: [done]
      userdata: {c: 3}
      input_keys: [c, d]
      transitions: {done: done}
      states:
        - IN: {template: T, userdata: {e: 4}, transitions: {ok: done}}
)");
  const ir::Module& m = *c->module;
  UserdataScope root(m, m.root());
  REQUIRE(root.literals().size() == 2);
  CHECK(root.keyName(root.literals()[0].key) == "a");
  CHECK(root.literals()[0].child == UserdataScope::kContainer);
  CHECK(root.keyName(root.literals()[1].key) == "b");
  REQUIRE(root.find("c").has_value());  // read by SUB, so interned
  CHECK_FALSE(root.initiallyDefined(*root.find("c")));
  REQUIRE(root.reads(0).size() == 1);
  CHECK(root.keyName(root.reads(0)[0].key) == "a");
  CHECK(root.reads(0)[0].name->text == "k");
  REQUIRE(root.reads(1).size() == 2);
  CHECK(root.reads(1)[0].optional);        // SUB has its own default for `c`
  CHECK_FALSE(root.reads(1)[1].optional);  // but not for `d`
  auto writer = root.firstWriter(*root.find("o"));
  REQUIRE(writer.has_value());
  CHECK(writer->first == 0);
  UserdataScope sub(m, find(m, "SUB"));
  CHECK(sub.initiallyDefined(*sub.find("c")));
  CHECK(sub.initiallyDefined(*sub.find("d")));
  CHECK(sub.initiallyDefined(*sub.find("e")));
}

TEST_CASE("must-defined: joins intersect, loops are followed, unreachable reads are skipped") {
  auto c = lower(kDiamond);
  CHECK(maybeUndefined(*c, kDefaultBudgetWords) == std::vector<std::string>{"JOIN:x", "JOIN:z"});
}

TEST_CASE("must-defined: small chunks give the same answer as one big chunk") {
  std::string script =
      "name: w\ntemplate: Base\noutcomes: [done]\nstates:\n"
      "  - START: {template: T, outcomes: [a, b], transitions: {a: W1, b: W2}}\n";
  std::string all, half;
  for (int k = 0; k < 150; ++k) {
    all += (k ? ", k" : "k") + std::to_string(k);
    if (k % 2 == 0) half += (half.empty() ? "k" : ", k") + std::to_string(k);
  }
  script +=
      "  - W1: {template: T, outcomes: [ok], output_keys: [" + all + "], transitions: {ok: R}}\n";
  script +=
      "  - W2: {template: T, outcomes: [ok], output_keys: [" + half + "], transitions: {ok: R}}\n";
  script +=
      "  - R: {template: T, outcomes: [ok], input_keys: [" + all + "], transitions: {ok: done}}\n";
  auto c = lower(script);
  std::vector<std::string> one_chunk = maybeUndefined(*c, kDefaultBudgetWords);
  CHECK(one_chunk.size() == 75);
  CHECK(one_chunk.front() == "R:k1");
  CHECK(maybeUndefined(*c, 1) == one_chunk);  // one 64-bit word per state: three chunks
}

/// A random script: `states` leaves with up to three outcomes going to random siblings or to
/// `done`, reading and writing random keys among k0..k5 (k0 defined by the root).
std::string randomScript(std::mt19937& rng, int states) {
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  std::string s = "name: r\ntemplate: Base\noutcomes: [done]\nuserdata: {k0: 0}\nstates:\n";
  for (int i = 0; i < states; ++i) {
    std::string outcomes, transitions, reads, writes;
    for (int o = 0; o <= pick(3); ++o) {
      int target = pick(states + 1);
      std::string name = "o" + std::to_string(o);
      outcomes += (o ? ", " : "") + name;
      transitions += (o ? ", " : "") + name + ": " +
                     (target == states ? "done" : "S" + std::to_string(target));
    }
    for (int k = 0; k < 6; ++k) {
      if (pick(4) == 0) reads += (reads.empty() ? "k" : ", k") + std::to_string(k);
      if (pick(5) == 0) writes += (writes.empty() ? "k" : ", k") + std::to_string(k);
    }
    s += "  - S" + std::to_string(i) + ": {template: T, outcomes: [" + outcomes +
         "], input_keys: [" + reads + "], output_keys: [" + writes + "], transitions: {" +
         transitions + "}}\n";
  }
  return s;
}

/// Must-defined by brute force: a fixpoint over key masks, then every read of a reachable
/// state whose key is not in IN.
std::set<std::pair<uint32_t, uint32_t>> referenceUndefined(const ContainerGraph& g,
                                                           const UserdataScope& scope) {
  std::vector<uint8_t> reachable = reachableFromStart(g);
  uint64_t initial = 0;
  for (uint32_t k = 0; k < scope.keyCount(); ++k)
    initial |= uint64_t{scope.initiallyDefined(k)} << k;
  std::vector<uint64_t> in(g.size(), ~uint64_t{0});
  auto out = [&](uint32_t n) {
    uint64_t m = in[n];
    for (const KeyUse& w : scope.writes(n)) m |= uint64_t{1} << w.key;
    return m;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (uint32_t n = 0; n < g.size(); ++n) {
      if (!reachable[n]) continue;
      uint64_t m = n == 0 ? initial : ~uint64_t{0};
      for (uint32_t p = 0; p < g.size(); ++p) {
        for (uint32_t s : g.successors(p)) {
          if (s == n && reachable[p]) m &= out(p);
        }
      }
      if (m != in[n]) in[n] = m, changed = true;
    }
  }
  std::set<std::pair<uint32_t, uint32_t>> undefined;
  for (uint32_t n = 0; n < g.size(); ++n) {
    for (const KeyUse& r : scope.reads(n)) {
      if (reachable[n] && scope.written(r.key) && !((in[n] >> r.key) & 1))
        undefined.emplace(n, r.key);
    }
  }
  return undefined;
}

/// Whether `d` dominates `n`: `n` is unreachable once `d` is removed (d == n counts).
bool dominates(const ContainerGraph& g, uint32_t d, uint32_t n) {
  if (d == n || d == 0) return true;
  std::vector<uint8_t> seen(g.size(), 0);
  std::vector<uint32_t> stack{0};
  seen[0] = seen[d] = 1;
  while (!stack.empty()) {
    uint32_t x = stack.back();
    stack.pop_back();
    if (x == n) return false;
    for (uint32_t s : g.successors(x)) {
      if (!seen[s]) seen[s] = 1, stack.push_back(s);
    }
  }
  return true;
}

TEST_CASE("dominators and must-defined agree with brute force on random graphs") {
  std::mt19937 rng(20240607);
  for (int round = 0; round < 60; ++round) {
    auto c = lower(randomScript(rng, 3 + round % 25));
    const ir::Module& m = *c->module;
    ContainerGraph g = buildContainerGraph(m, m.root(), ChildIndex(m));
    std::vector<uint8_t> reachable = reachableFromStart(g);
    std::vector<uint32_t> idom = immediateDominators(g, reverseGraph(g));
    for (uint32_t n = 1; n < g.size(); ++n) {
      if (!reachable[n]) {
        CHECK(idom[n] == kNoDominator);
        continue;
      }
      REQUIRE(idom[n] != kNoDominator);
      CHECK(dominates(g, idom[n], n));
      for (uint32_t d = 0; d < g.size(); ++d) {  // every strict dominator dominates idom
        if (d != n && reachable[d] && dominates(g, d, n)) CHECK(dominates(g, d, idom[n]));
      }
    }
    UserdataScope scope(m, m.root());
    std::set<std::pair<uint32_t, uint32_t>> found;
    for (const UndefinedRead& r : findMaybeUndefinedReads(g, scope, 1)) {
      found.emplace(r.child, r.use->key);
    }
    CHECK(found == referenceUndefined(g, scope));
  }
}

TEST_CASE("identifier rules depend on the target") {
  CHECK(identifierRules("smach") == IdentifierRules::Python);
  CHECK(identifierRules("flexbe") == IdentifierRules::Python);
  CHECK(identifierRules("cpp") == IdentifierRules::Cpp);
  CHECK(identifierRules("ir") == IdentifierRules::None);
  CHECK(identifierRules("json") == IdentifierRules::None);
  auto python = [](std::string_view s) { return identifierProblem(s, IdentifierRules::Python); };
  auto cpp = [](std::string_view s) { return identifierProblem(s, IdentifierRules::Cpp); };
  CHECK_FALSE(python("pose_2").has_value());
  CHECK_FALSE(python("match").has_value());  // a soft keyword only
  CHECK(python("None") == "is a keyword");
  CHECK(python("2x") == "starts with a digit");
  CHECK(python("a-b") == "contains `-`");
  CHECK(python("a b") == "contains a space");
  CHECK(python("") == "is empty");
  CHECK(python("caf\xc3\xa9") == "contains a non-ASCII character");
  CHECK(cpp("class") == "is a keyword");
  CHECK_FALSE(cpp("None").has_value());
  CHECK(cpp("a__b") == "contains `__` (reserved)");
  CHECK(cpp("_Tmp") == "starts with `_` and a capital letter (reserved)");
  CHECK_FALSE(cpp("_tmp").has_value());
  CHECK_FALSE(identifierProblem("a-b", IdentifierRules::None).has_value());
  CHECK(asciiLower("PICK_Block") == "pick_block");
}

}  // namespace
}  // namespace smachac::passes
