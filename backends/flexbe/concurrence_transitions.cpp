// Derived transitions of Concurrence children, for the FlexBE editor.
#include "backends/flexbe/concurrence_transitions.h"

#include <algorithm>

namespace smachac::backends::flexbe {
namespace {

bool connects(const ir::State& child, std::string_view outcome) {
  return std::any_of(child.transitions.begin(), child.transitions.end(),
                     [&](const ir::Transition& t) { return t.outcome.text == outcome; });
}

void connect(ir::State& child, const ir::Name& outcome, const ir::Name& container_outcome) {
  if (connects(child, outcome.text)) return;
  child.transitions.push_back({.outcome = outcome,
                               .target = container_outcome,
                               .target_kind = ir::TargetKind::ContainerOutcome,
                               .target_state = {}});
}

void deriveTransitions(const ir::State& concurrence, ir::State& child) {
  for (const ir::OutcomeMapEntry& entry : concurrence.outcome_map) {
    for (const ir::OutcomeCondition& condition : entry.conditions) {
      if (condition.child.text == child.name.text) {
        connect(child, condition.child_outcome, entry.outcome);
      }
    }
  }
  if (!concurrence.default_outcome) return;
  for (const ir::Name& outcome : child.outcomes)
    connect(child, outcome, *concurrence.default_outcome);
}

}  // namespace

ir::Module withConcurrenceTransitions(const ir::Module& module) {
  ir::Module derived = module;
  for (ir::StateId id : derived.preorder()) {
    const ir::State& state = derived.state(id);
    if (state.kind != ir::StateKind::Concurrence) continue;
    for (ir::StateId child_id : state.children) {
      ir::State& child = derived.state(child_id);
      if (child.transitions.empty()) deriveTransitions(state, child);
    }
  }
  return derived;
}

}  // namespace smachac::backends::flexbe
