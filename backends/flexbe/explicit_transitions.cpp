// Explicit transitions for the FlexBE target.
#include "backends/flexbe/explicit_transitions.h"

#include <algorithm>
#include <optional>

namespace smachac::backends::flexbe {
namespace {

constexpr size_t kMaxDefaultConditions = 64;

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

/// Whether an outcome_map entry holds whenever the children finish with `combination`, so
/// that a default condition for it would never be reached. Entries without conditions do not
/// count: SMACH 2.5 never chooses them (stdlib/runtime/README.md), and they are not written.
bool matchesOutcomeMap(const ir::State& concurrence, const ir::List& combination) {
  auto finished_with = [&](const ir::OutcomeCondition& c) {
    return std::any_of(combination.begin(), combination.end(), [&](const ir::Value& pair) {
      return pair.asList()[0].asString() == c.child.text &&
             pair.asList()[1].asString() == c.child_outcome.text;
    });
  };
  return std::any_of(concurrence.outcome_map.begin(), concurrence.outcome_map.end(),
                     [&](const ir::OutcomeMapEntry& entry) {
                       return !entry.conditions.empty() &&
                              std::all_of(entry.conditions.begin(), entry.conditions.end(),
                                          finished_with);
                     });
}

/// Every combination of the children's outcomes that no outcome_map entry matches, as
/// [[child, outcome], ...] lists; nullopt when there are more than kMaxDefaultConditions.
std::optional<ir::Value> outcomeCombinations(const ir::Module& module, const ir::State& concurrence,
                                             const TemplateOutcomes& template_outcomes) {
  std::vector<ir::List> combinations{{}};
  for (ir::StateId child_id : concurrence.children) {
    const ir::State& child = module.state(child_id);
    std::vector<ir::Name> outcomes = allOutcomes(child, template_outcomes);
    if (outcomes.empty()) continue;
    if (combinations.size() * outcomes.size() > kMaxDefaultConditions) return std::nullopt;
    std::vector<ir::List> extended;
    for (const ir::List& combination : combinations) {
      for (const ir::Name& outcome : outcomes) {
        ir::List pairs = combination;
        pairs.push_back(
            ir::Value::list({ir::Value::string(child.name.text), ir::Value::string(outcome.text)}));
        extended.push_back(std::move(pairs));
      }
    }
    combinations = std::move(extended);
  }
  ir::List conditions;
  for (ir::List& combination : combinations) {
    if (!matchesOutcomeMap(concurrence, combination)) {
      conditions.push_back(ir::Value::list(std::move(combination)));
    }
  }
  return ir::Value::list(std::move(conditions));
}

/// The conditions that stand for `default_outcome`, as the argument `default_conditions`.
void addDefaultConditions(ir::Module& module, ir::StateId id,
                          const TemplateOutcomes& template_outcomes, DiagnosticEmitter& diags) {
  const ir::State& concurrence = module.state(id);
  if (!concurrence.default_outcome || concurrence.children.empty()) return;
  std::optional<ir::Value> conditions = outcomeCombinations(module, concurrence, template_outcomes);
  if (!conditions) {
    diags.emit<DiagKind::FlexbeDefaultOutcomeLost>(concurrence.default_outcome->loc,
                                                   concurrence.name.text, kMaxDefaultConditions,
                                                   concurrence.default_outcome->text);
    return;
  }
  module.state(id).args.push_back({{"default_conditions", {}}, std::move(*conditions)});
}

}  // namespace

ir::Module withExplicitTransitions(const ir::Module& module,
                                   const TemplateOutcomes& template_outcomes,
                                   DiagnosticEmitter& diags) {
  ir::Module connected = module;
  for (ir::StateId id : connected.preorder()) {
    if (connected.state(id).kind == ir::StateKind::Concurrence) {
      addDefaultConditions(connected, id, template_outcomes, diags);
    }
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
