// Explicit transitions for the FlexBE target.
#include "backends/flexbe/explicit_transitions.h"

#include <algorithm>

namespace smachac::backends::flexbe {
namespace {

bool connects(const ir::State& child, std::string_view outcome) {
  return std::any_of(child.transitions.begin(), child.transitions.end(),
                     [&](const ir::Transition& t) { return t.outcome.text == outcome; });
}

bool hasOutcome(const ir::State& state, std::string_view outcome) {
  return std::any_of(state.outcomes.begin(), state.outcomes.end(),
                     [&](const ir::Name& o) { return o.text == outcome; });
}

void connect(ir::State& child, const ir::Name& outcome, const ir::Name& container_outcome) {
  if (connects(child, outcome.text)) return;
  child.transitions.push_back({.outcome = outcome,
                               .target = container_outcome,
                               .target_kind = ir::TargetKind::ContainerOutcome,
                               .target_state = {}});
}

/// The script's outcomes of `state`, then its template's that the script does not list.
std::vector<ir::Name> allOutcomes(const ir::State& state,
                                  const TemplateOutcomes& template_outcomes) {
  std::vector<ir::Name> outcomes = state.outcomes;
  if (state.kind != ir::StateKind::Leaf || !state.template_name) return outcomes;
  for (const std::string& outcome : template_outcomes(state.template_name->text)) {
    if (!hasOutcome(state, outcome)) outcomes.push_back({outcome, state.template_name->loc});
  }
  return outcomes;
}

void deriveFromOutcomeMap(const ir::State& concurrence, ir::State& child,
                          const std::vector<ir::Name>& outcomes) {
  for (const ir::OutcomeMapEntry& entry : concurrence.outcome_map) {
    for (const ir::OutcomeCondition& condition : entry.conditions) {
      if (condition.child.text == child.name.text) {
        connect(child, condition.child_outcome, entry.outcome);
      }
    }
  }
  if (!concurrence.default_outcome) return;
  for (const ir::Name& outcome : outcomes) connect(child, outcome, *concurrence.default_outcome);
}

}  // namespace

ir::Module withExplicitTransitions(const ir::Module& module,
                                   const TemplateOutcomes& template_outcomes) {
  ir::Module connected = module;
  for (ir::StateId id : connected.preorder()) {
    const ir::State& container = connected.state(id);
    for (ir::StateId child_id : container.children) {
      ir::State& child = connected.state(child_id);
      std::vector<ir::Name> outcomes = allOutcomes(child, template_outcomes);
      if (container.kind == ir::StateKind::Concurrence && child.transitions.empty()) {
        deriveFromOutcomeMap(container, child, outcomes);
      }
      for (const ir::Name& outcome : outcomes) {
        if (hasOutcome(container, outcome.text)) connect(child, outcome, outcome);
      }
    }
  }
  return connected;
}

}  // namespace smachac::backends::flexbe
