// One state of the state graph: a leaf, a container (StateMachine, Concurrence) or the script
// root (Base). Core script keys are typed fields; every other key of the script is kept, in
// order, as a typed template argument. Every field keeps the location it came from.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ir/boxed.h"
#include "ir/ids.h"
#include "ir/state_kind.h"
#include "ir/symbol.h"
#include "ir/value.h"

namespace smachac::ir {

/// A name as written in the script, with its location (24 bytes: a big script holds millions).
struct Name {
  Symbol text;
  SourceLoc loc;
};

/// Where a transition goes: a sibling state, an outcome of the enclosing container, or a
/// name that is neither (reported by the transition checks).
enum class TargetKind : uint8_t { Unresolved, Sibling, ContainerOutcome };

/// "unresolved", "state" or "outcome", as the IR printers show it.
std::string_view targetKindName(TargetKind kind);

struct Transition {
  Name outcome;
  Name target;
  TargetKind target_kind = TargetKind::Unresolved;
  StateId target_state;  ///< valid when target_kind == Sibling
};

/// `remapping: {state_key: parent_key}`.
struct Remap {
  Name key;
  Name parent_key;
};

/// A named value: userdata entries, callbacks and template arguments.
struct Argument {
  Name key;
  Value value;
};

/// `outcome_map: {container_outcome: {child: child_outcome, ...}}`.
struct OutcomeCondition {
  Name child;
  Name child_outcome;
};
struct OutcomeMapEntry {
  Name outcome;
  std::vector<OutcomeCondition> conditions;
};

/// A state that came from a sub-script: the file it was read from, the `script:` key of the
/// including state, the other keys the including state set, and the sub-script state's own
/// `params` (before the caller's were merged in).
struct Inclusion {
  uint32_t file = 0;
  Name script;
  std::vector<Name> caller_keys;
  std::optional<Value> script_params;
};

struct State {
  StateKind kind = StateKind::Leaf;
  Name name;
  SourceLoc loc;  ///< the state's mapping in the script
  StateId parent;
  std::vector<StateId> children;

  std::optional<Name> template_name;
  std::vector<Name> outcomes;
  std::vector<Name> input_keys;
  std::vector<Name> output_keys;
  std::vector<Transition> transitions;
  std::vector<Remap> remapping;
  std::vector<Argument> userdata;
  Boxed<Value> params;  ///< a map, after inheritance
  std::vector<Argument> callbacks;
  std::vector<OutcomeMapEntry> outcome_map;
  Boxed<Name> default_outcome;
  std::vector<Argument> args;            ///< every other key, in script order
  std::vector<Inclusion> included_from;  ///< innermost first; empty if written in place

  const Argument* findArg(std::string_view key) const;
};

}  // namespace smachac::ir
