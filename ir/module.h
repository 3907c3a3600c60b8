// ir::Module owns a compiled script: every state in one store addressed by StateId, the root
// (a Base state), and the files the script was read from (ids into the SourceManager).
#pragma once

#include <deque>
#include <span>
#include <string>
#include <vector>

#include "ir/ids.h"
#include "ir/state.h"
#include "ir/support/check.h"

namespace smachac::ir {

/// A parameter of a behavior: a key of the `params` of the script's root or of a state
/// included from a sub-script (`scope`), whose values the lookups below it copy.
struct BehaviorParam {
  StateId scope;
  std::string name;
};

class Module {
 public:
  StateId addState(State state);
  /// Inline: the passes look states up hundreds of times per state.
  State& state(StateId id) {
    SMACHAC_CHECK(id.valid() && id.index < states_.size(), "dangling StateId");
    return states_[id.index];
  }
  const State& state(StateId id) const {
    SMACHAC_CHECK(id.valid() && id.index < states_.size(), "dangling StateId");
    return states_[id.index];
  }
  size_t stateCount() const { return states_.size(); }

  StateId root() const { return root_; }
  void setRoot(StateId id) { root_ = id; }

  /// Appends `child` to `parent`'s children and sets its parent.
  void adopt(StateId parent, StateId child);
  /// The child of `container` named `name`, or an invalid id.
  StateId findChild(StateId container, std::string_view name) const;
  /// Names from the root to `id`, joined by '/': "ROOT/SUB/FOO".
  std::string path(StateId id) const;

  /// States in document order (pre-order from the root); detached states are skipped.
  std::vector<StateId> preorder() const;

  /// Registers a behavior parameter; the result is the non-zero `Value::behavior_param`.
  uint32_t addBehaviorParam(StateId scope, std::string name);
  /// The reference of parameter `name` of `scope`, or 0.
  uint32_t findBehaviorParam(StateId scope, std::string_view name) const;

  /// The main script's file id, then every sub-script file, in first-read order.
  std::vector<uint32_t>& files() { return files_; }
  const std::vector<uint32_t>& files() const { return files_; }

 private:
  std::deque<State> states_;
  StateId root_;
  std::vector<uint32_t> files_;
  std::vector<BehaviorParam> behavior_params_;
};

}  // namespace smachac::ir
