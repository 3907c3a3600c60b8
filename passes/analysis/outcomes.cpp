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

namespace {

/// Small states (the usual ones) are scanned; large ones go through a hash set.
constexpr size_t kLinearScanLimit = 16;

/// Calls `each` on every outcome of `state` without a transition, once per name, in order.
template <typename Each>
void forEachUnmapped(const ir::State& state, Each each) {
  if (state.outcomes.size() + state.transitions.size() <= kLinearScanLimit) {
    for (size_t i = 0; i < state.outcomes.size(); ++i) {
      const ir::Name& outcome = state.outcomes[i];
      bool repeated = false;
      for (size_t j = 0; j < i && !repeated; ++j) repeated = state.outcomes[j].text == outcome.text;
      if (!repeated && !findTransition(state, outcome.text) && each(outcome)) return;
    }
    return;
  }
  NameSet mapped;
  for (const ir::Transition& t : state.transitions) mapped.insert(t.outcome.text);
  for (const ir::Name& outcome : state.outcomes) {
    if (mapped.insert(outcome.text).second && each(outcome)) return;
  }
}

}  // namespace

std::vector<const ir::Name*> unmappedOutcomes(const ir::State& state) {
  std::vector<const ir::Name*> unmapped;
  forEachUnmapped(state, [&](const ir::Name& outcome) {
    unmapped.push_back(&outcome);
    return false;
  });
  return unmapped;
}

bool canEndContainer(const ir::State& child, const NameSet& container_outcomes) {
  if (!declaresOutcomes(child)) return true;
  for (const ir::Transition& t : child.transitions) {
    if (t.target_kind == ir::TargetKind::ContainerOutcome) return true;
  }
  bool ends = false;
  forEachUnmapped(child, [&](const ir::Name& outcome) {
    ends = container_outcomes.contains(outcome.text);
    return ends;
  });
  return ends;
}

}  // namespace smachac::passes
