// Outcome facts: declared, mapped and pass-through outcomes.
#include "passes/analysis/outcomes.h"

namespace smachac::passes {

NameSet nameSet(const std::vector<ir::Name>& names) {
  NameSet set;
  set.reserve(names.size());
  for (const ir::Name& name : names) set.insert(name.text);
  return set;
}

std::vector<std::string> nameTexts(const std::vector<ir::Name>& names) {
  std::vector<std::string> texts;
  texts.reserve(names.size());
  for (const ir::Name& name : names) texts.push_back(name.text);
  return texts;
}

bool contains(const std::vector<ir::Name>& names, std::string_view text) {
  for (const ir::Name& name : names) {
    if (name.text == text) return true;
  }
  return false;
}

const ir::Transition* findTransition(const ir::State& state, std::string_view outcome) {
  for (const ir::Transition& t : state.transitions) {
    if (t.outcome.text == outcome) return &t;
  }
  return nullptr;
}

std::vector<const ir::Name*> unmappedOutcomes(const ir::State& state) {
  std::vector<const ir::Name*> unmapped;
  NameSet mapped;
  for (const ir::Transition& t : state.transitions) mapped.insert(t.outcome.text);
  for (const ir::Name& outcome : state.outcomes) {
    if (mapped.insert(outcome.text).second) unmapped.push_back(&outcome);
  }
  return unmapped;
}

bool canEndContainer(const ir::State& child, const NameSet& container_outcomes) {
  if (!declaresOutcomes(child)) return true;
  for (const ir::Transition& t : child.transitions) {
    if (t.target_kind == ir::TargetKind::ContainerOutcome) return true;
  }
  for (const ir::Name* outcome : unmappedOutcomes(child)) {
    if (container_outcomes.contains(outcome->text)) return true;
  }
  return false;
}

}  // namespace smachac::passes
