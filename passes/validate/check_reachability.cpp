// check-reachability: the transition graph of every StateMachine and of the root
// (passes/analysis/container_graph.h; what can end a container is in outcomes.h).
//   * empty-container           a container without states (SMACH: a StateMachine has no
//                               initial state; an empty Concurrence never finishes)
//   * unreachable-state         a state no path of transitions leads to from the initial
//                               state (the first one)
//   * container-never-finishes  a container that declares no outcomes, or whose initial state
//                               has no path to any of them
//   * no-path-to-outcome        a reachable state with no path to an outcome of its container
//                               (a livelock, unless something preempts the machine); not
//                               reported inside containers that can never finish
#include <fmt/core.h>

#include <algorithm>

#include "passes/analysis/container_graph.h"
#include "passes/analysis/outcomes.h"
#include "passes/validate/checks.h"

namespace smachac::passes {
namespace {

const ir::Name& nodeName(const ir::Module& module, const ContainerGraph& graph, uint32_t node) {
  return module.state(graph.nodes[node]).name;  // nodes are the children, in order
}

void reportUnreachable(const ir::Module& module, const ir::State& container,
                       const ContainerGraph& graph, const std::vector<uint8_t>& reachable,
                       DiagnosticEmitter& diags) {
  if (std::find(reachable.begin(), reachable.end(), 0) == reachable.end()) return;
  const std::string& initial = nodeName(module, graph, 0).text;
  NameSet names;  // a second state of the same name is a duplicate-state-name error already
  for (uint32_t node = 0; node < graph.size(); ++node) {
    const ir::Name& name = nodeName(module, graph, node);
    if (!names.insert(name.text).second || reachable[node]) continue;
    diags.emit<DiagKind::UnreachableState>(name.loc, name.text, initial, container.name.text);
  }
}

/// Reports a container that cannot finish; returns whether it can.
bool checkCanFinish(const ir::Module& module, const ir::State& container,
                    const ContainerGraph& graph, const std::vector<uint8_t>& exits_reachable,
                    DiagnosticEmitter& diags) {
  std::string reason;
  if (container.outcomes.empty()) {
    reason = "it declares no outcomes";
  } else if (!exits_reachable[0]) {
    reason = fmt::format("no path from its initial state `{}` reaches one of its outcomes",
                         nodeName(module, graph, 0).text);
  } else {
    return true;
  }
  diags.emit<DiagKind::ContainerNeverFinishes>(container.name.loc, container.name.text, reason);
  return false;
}

void checkSequential(const ir::Module& module, ir::StateId id, const ChildIndex& index,
                     DiagnosticEmitter& diags) {
  const ir::State& container = module.state(id);
  ContainerGraph graph = buildContainerGraph(module, id, index);
  std::vector<uint8_t> reachable = reachableFromStart(graph);
  reportUnreachable(module, container, graph, reachable, diags);
  std::vector<uint8_t> exits_reachable = canReachExit(graph);
  if (!checkCanFinish(module, container, graph, exits_reachable, diags)) return;
  for (uint32_t node = 0; node < graph.size(); ++node) {
    if (!reachable[node] || exits_reachable[node]) continue;
    const ir::Name& name = nodeName(module, graph, node);
    diags.emit<DiagKind::NoPathToOutcome>(name.loc, name.text, container.name.text);
  }
}

}  // namespace

void checkReachability(const ir::Module& module, PassContext& context) {
  ChildIndex index(module);
  for (ir::StateId id : module.preorder()) {
    const ir::State& state = module.state(id);
    if (!ir::isContainer(state.kind)) continue;
    if (state.children.empty()) {
      context.diags.emit<DiagKind::EmptyContainer>(state.name.loc, state.name.text);
    } else if (isSequential(state.kind)) {
      checkSequential(module, id, index, context.diags);
    }
  }
}

}  // namespace smachac::passes
