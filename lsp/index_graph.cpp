// indexStateGraph (index_builder.h): the names of the state graph, from the module. A
// transition's target is the sibling state or the container outcome the frontend resolved it
// to (an unresolved one names nothing); an outcome_map condition names a child and one of its
// outcomes; a transition's key and `default_outcome` name outcomes of their own state.
#include "lsp/index_builder.h"

namespace smachac::lsp {
namespace {

using ir::StateId;

void indexTarget(const ir::State& state, StateId id, const ir::Transition& t, IndexBuilder& b) {
  if (t.target_kind == ir::TargetKind::Sibling && t.target_state.valid()) {
    b.add(t.target, b.state(t.target_state, t.target.text), Role::Reference, Site::TransitionTarget,
          id, t.target_state);
  } else if (t.target_kind == ir::TargetKind::ContainerOutcome && state.parent.valid()) {
    b.add(t.target, b.outcome(state.parent, t.target.text), Role::Reference, Site::TransitionTarget,
          id, state.parent);
  }
}

void indexOutcomeMap(const ir::Module& module, StateId id, IndexBuilder& b) {
  for (const ir::OutcomeMapEntry& entry : module.state(id).outcome_map) {
    b.add(entry.outcome, b.outcome(id, entry.outcome.text), Role::Reference,
          Site::OutcomeMapOutcome, id, id);
    for (const ir::OutcomeCondition& condition : entry.conditions) {
      StateId child = module.findChild(id, condition.child.text);
      if (!child.valid()) continue;
      b.add(condition.child, b.state(child, condition.child.text), Role::Reference,
            Site::OutcomeMapChild, id, child);
      b.add(condition.child_outcome, b.outcome(child, condition.child_outcome.text),
            Role::Reference, Site::OutcomeMapChildOutcome, id, child);
    }
  }
}

void indexOutcomes(const ir::State& s, StateId id, IndexBuilder& b) {
  for (const ir::Name& outcome : s.outcomes) {
    b.add(outcome, b.outcome(id, outcome.text), Role::Definition, Site::Outcomes, id, id);
  }
  for (const ir::Transition& t : s.transitions) {
    b.add(t.outcome, b.outcome(id, t.outcome.text), Role::Reference, Site::TransitionOutcome, id,
          id);
    indexTarget(s, id, t, b);
  }
  if (s.default_outcome) {
    b.add(*s.default_outcome, b.outcome(id, s.default_outcome->text), Role::Reference,
          Site::DefaultOutcome, id, id);
  }
}

void indexState(const ir::Module& module, StateId id, IndexBuilder& b) {
  const ir::State& s = module.state(id);
  b.add(s.name, b.state(id, s.name.text), Role::Definition, Site::StateName, id, id);
  if (s.template_name) {
    b.add(*s.template_name, b.templateName(s.template_name->text), Role::Reference, Site::Template,
          id, id);
  }
  for (const ir::Inclusion& inclusion : s.included_from) {
    b.add(inclusion.script, b.subScript(inclusion.file, inclusion.script.text), Role::Reference,
          Site::Script, id, id);
  }
  indexOutcomes(s, id, b);
  indexOutcomeMap(module, id, b);
}

}  // namespace

void indexStateGraph(const ir::Module& module, IndexBuilder& builder) {
  for (StateId id : module.preorder()) indexState(module, id, builder);
}

}  // namespace smachac::lsp
