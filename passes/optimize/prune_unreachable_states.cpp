// prune-unreachable-states: removes the states of a StateMachine (or of the root) that no
// path of transitions reaches from the initial state, with everything inside them.
//
//   before                                      after
//   base SEQ  outcomes: [done]                  base SEQ  outcomes: [done]
//     leaf A  {succeeded -> done (outcome)}       userdata: {x: 1}          (from B)
//     leaf B  userdata: {x: 1}                    leaf A  {succeeded -> done (outcome)}
//             {succeeded -> A (state)}
//
// A pruned leaf's `userdata` still defined keys of its container when the container was
// built (passes/analysis/userdata_scope.h), so an entry that was the last definition of its key
// moves to the container's own `userdata`, and the earlier definitions it overrode are
// dropped; the pruned state's other entries were overridden and go with it.
#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "passes/analysis/container_graph.h"
#include "passes/analysis/outcomes.h"
#include "passes/optimize/transforms.h"

namespace smachac::passes {
namespace {

constexpr uint32_t kContainer = UINT32_MAX;

void setUserdata(ir::State& container, ir::Argument entry) {
  for (ir::Argument& existing : container.userdata) {
    if (existing.key.text == entry.key.text) {
      existing = std::move(entry);
      return;
    }
  }
  container.userdata.push_back(std::move(entry));
}

/// Moves the effective userdata of the children that are not `reachable` to the container.
void hoistUserdata(ir::Module& module, ir::State& container,
                   const std::vector<uint8_t>& reachable) {
  auto in_scope = [&](uint32_t i) {
    return !ir::isContainer(module.state(container.children[i]).kind);
  };
  std::unordered_map<std::string, uint32_t> last;  // key -> last defining child
  for (const ir::Argument& entry : container.userdata) last[entry.key.text] = kContainer;
  for (uint32_t i = 0; i < container.children.size(); ++i) {
    if (!in_scope(i)) continue;
    for (const ir::Argument& entry : module.state(container.children[i]).userdata) {
      last[entry.key.text] = i;
    }
  }
  std::unordered_set<std::string> hoisted;
  for (uint32_t i = 0; i < container.children.size(); ++i) {
    if (reachable[i] || !in_scope(i)) continue;
    for (ir::Argument& entry : module.state(container.children[i]).userdata) {
      if (last[entry.key.text] != i) continue;
      hoisted.insert(entry.key.text);
      setUserdata(container, std::move(entry));
    }
  }
  if (hoisted.empty()) return;
  for (uint32_t i = 0; i < container.children.size(); ++i) {
    if (!reachable[i] || !in_scope(i)) continue;
    std::erase_if(module.state(container.children[i]).userdata,
                  [&](const ir::Argument& entry) { return hoisted.contains(entry.key.text); });
  }
}

bool pruneContainer(ir::Module& module, ir::StateId id, const ChildIndex& index) {
  ContainerGraph graph = buildContainerGraph(module, id, index);
  std::vector<uint8_t> reachable = reachableFromStart(graph);
  if (std::find(reachable.begin(), reachable.end(), 0) == reachable.end()) return false;
  ir::State& container = module.state(id);
  hoistUserdata(module, container, reachable);
  std::vector<ir::StateId> kept;
  for (uint32_t node = 0; node < graph.size(); ++node) {
    if (reachable[node]) {
      kept.push_back(graph.nodes[node]);
    } else {
      module.state(graph.nodes[node]).parent = ir::StateId();
    }
  }
  container.children = std::move(kept);
  return true;
}

}  // namespace

bool pruneUnreachableStates(ir::Module& module, PassContext&) {
  ChildIndex index(module);
  bool changed = false;
  std::vector<uint8_t> pruned(module.stateCount(), 0);
  for (ir::StateId id : module.preorder()) {
    const ir::State& state = module.state(id);
    bool detached = id != module.root() && (!state.parent.valid() || pruned[state.parent.index]);
    if (detached) {
      pruned[id.index] = 1;
      continue;
    }
    if (isSequential(state.kind) && !state.children.empty()) {
      changed = pruneContainer(module, id, index) || changed;
    }
  }
  return changed;
}

}  // namespace smachac::passes
