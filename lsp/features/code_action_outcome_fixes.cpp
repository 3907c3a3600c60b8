// Quick fixes for transitions and outcomes (check-transitions, check-concurrence):
//   * unmapped-outcome: add a transition for the outcome to the next state of the container,
//     or to each outcome of the container; or add the outcome to the container's outcomes
//     (then it ends the container)
//   * unknown-transition-target: add the target to the outcomes of the container
//   * undeclared-outcome: add the outcome to the outcomes of the state that has the
//     transition (or that the concurrence's `outcome_map` names)
#include <fmt/core.h>

#include "lsp/features/code_action_fixes.h"
#include "refactor/flow_text.h"

namespace smachac::lsp {
namespace {

void addOutcome(FixContext& fix, const ir::State& state, const std::string& outcome) {
  const ir::Value* mapping = listOwner(fix, state, "outcomes");
  if (!mapping) return;
  YamlEdit edit = fix.edit();
  if (!edit.addToList(*mapping, "outcomes", outcome)) return;
  fix.offer(fmt::format("Add outcome `{}` to `{}`", outcome, state.name.text), edit.result());
}

/// Where an outcome without a transition may go: the next state, then the container's
/// outcomes.
std::vector<std::string> transitionTargets(const ir::Module& module, const ir::State& state) {
  const ir::State& container = module.state(state.parent);
  std::vector<std::string> targets;
  for (size_t i = 0; i + 1 < container.children.size(); ++i) {
    if (&module.state(container.children[i]) == &state) {
      targets.push_back(module.state(container.children[i + 1]).name.text);
    }
  }
  for (const ir::Name& outcome : container.outcomes) targets.push_back(outcome.text);
  return targets;
}

void addTransitions(FixContext& fix, const ir::State& state, const std::string& outcome) {
  const ir::Value* mapping = stateMapping(fix.yaml(), state);
  if (!mapping) return;
  for (const std::string& target : transitionTargets(fix.module(), state)) {
    YamlEdit edit = fix.edit();
    if (!edit.addToMap(*mapping, "transitions", outcome, refactor::flowScalar(target))) return;
    fix.offer(fmt::format("Add transition `{}: {}` to `{}`", outcome, target, state.name.text),
              edit.result());
  }
}

void fixUnmappedOutcome(FixContext& fix) {
  const SourceLoc& at = fix.diagnostic().loc;
  const ir::State* state =
      fix.findState([&](const ir::State& s) { return s.parent.valid() && nameAt(s.outcomes, at); });
  if (!state) return;
  const std::string& outcome = nameAt(state->outcomes, at)->text;
  addTransitions(fix, *state, outcome);
  addOutcome(fix, fix.module().state(state->parent), outcome);
}

const ir::Transition* transitionWith(const ir::State& state, const SourceLoc& at, bool target) {
  for (const ir::Transition& t : state.transitions) {
    if ((target ? t.target.loc : t.outcome.loc) == at) return &t;
  }
  return nullptr;
}

void fixUnknownTarget(FixContext& fix) {
  const SourceLoc& at = fix.diagnostic().loc;
  const ir::State* state = fix.findState(
      [&](const ir::State& s) { return s.parent.valid() && transitionWith(s, at, true); });
  if (!state) return;
  addOutcome(fix, fix.module().state(state->parent), transitionWith(*state, at, true)->target.text);
}

struct NamedOutcome {
  const ir::State* state = nullptr;
  std::string outcome;
};

/// The state and outcome named at `at`: by one of the state's transitions, or by a condition
/// of its concurrence's `outcome_map`.
NamedOutcome outcomeNamedAt(const ir::Module& module, const SourceLoc& at) {
  for (ir::StateId id : module.preorder()) {
    const ir::State& state = module.state(id);
    if (const ir::Transition* t = transitionWith(state, at, false))
      return {&state, t->outcome.text};
    for (const ir::OutcomeMapEntry& entry : state.outcome_map) {
      for (const ir::OutcomeCondition& condition : entry.conditions) {
        if (condition.child_outcome.loc != at) continue;
        ir::StateId child = module.findChild(id, condition.child.text);
        if (!child.valid()) return {};
        return {&module.state(child), condition.child_outcome.text};
      }
    }
  }
  return {};
}

void fixUndeclaredOutcome(FixContext& fix) {
  NamedOutcome named = outcomeNamedAt(fix.module(), fix.diagnostic().loc);
  if (named.state) addOutcome(fix, *named.state, named.outcome);
}

}  // namespace

void addOutcomeFixes(FixContext& fix) {
  switch (fix.diagnostic().kind) {
    case DiagKind::UnmappedOutcome:
      return fixUnmappedOutcome(fix);
    case DiagKind::UnknownTransitionTarget:
      return fixUnknownTarget(fix);
    case DiagKind::UndeclaredOutcome:
      return fixUndeclaredOutcome(fix);
    default:
      return;
  }
}

}  // namespace smachac::lsp
