// Outcome facts the checks and transforms share. SMACH semantics (state_machine.py): a state's
// outcome with a transition goes to a sibling state or ends the container with the target
// outcome; an outcome without a transition ends the container with the same outcome, which
// must then be an outcome of the container.
//
// A leaf that lists no `outcomes` has outcomes nobody knows until template meta blocks exist
// (SMACHA scripts usually leave them to the template and map only `succeeded`, relying on
// `aborted` and `preempted` passing through): besides the outcomes its transitions map, it may
// end its container with any container outcome.
#pragma once

#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "ir/module.h"

namespace smachac::passes {

/// Containers whose children run one at a time, by transitions: StateMachine and the root.
inline bool isSequential(ir::StateKind kind) {
  return kind == ir::StateKind::StateMachine || kind == ir::StateKind::Base;
}

/// Whether the state's outcomes are known: a container's always, a leaf's when it lists them.
inline bool declaresOutcomes(const ir::State& state) {
  return ir::isContainer(state.kind) || !state.outcomes.empty();
}

/// Names for constant-time lookups; the views point into the IR, so the set lives no longer
/// than the IR stays unchanged.
using NameSet = std::unordered_set<std::string_view>;

NameSet nameSet(const std::vector<ir::Name>& names);
std::vector<std::string> nameTexts(const std::vector<ir::Name>& names);
bool contains(const std::vector<ir::Name>& names, std::string_view text);

const ir::Transition* findTransition(const ir::State& state, std::string_view outcome);

/// Declared outcomes of `state` that have no transition (each name once, in order).
std::vector<const ir::Name*> unmappedOutcomes(const ir::State& state);

/// Whether `child` of a sequential container whose outcomes are `container_outcomes` can end
/// the container directly: by a transition to a container outcome, by an unmapped outcome
/// that is a container outcome, or by having unknown outcomes. Unresolved transitions are not
/// counted (see buildContainerGraph).
bool canEndContainer(const ir::State& child, const NameSet& container_outcomes);

}  // namespace smachac::passes
