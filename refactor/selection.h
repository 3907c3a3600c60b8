// Which root states a tool works on, from names given on the command line. Rules:
//   * a name must be a root state: a state nested in a container is state-not-at-root (at
//     that state, naming its container); any other name is unknown-root-state (at the root
//     `states` key, with a suggestion and the list of root states)
//   * contain's names must be a run of consecutive root states, in script order, in one
//     list of states: otherwise selection-not-consecutive, at the first name that breaks the
//     run, with the actual sequence
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "ir/support/diagnostic_emitter.h"
#include "refactor/script_view.h"

namespace smachac::refactor {

/// A run of root states: indices [first, first + count).
struct Selection {
  size_t first = 0;
  size_t count = 0;

  bool contains(size_t index) const { return index >= first && index < first + count; }
  size_t last() const { return first + count - 1; }
};

/// The index of root state `name`; `tool` names the command in messages.
std::optional<size_t> findRootState(const ScriptView& script, std::string_view name,
                                    std::string_view tool, DiagnosticEmitter& diags);

/// The run of root states `names`.
std::optional<Selection> selectRun(const ScriptView& script, std::span<const std::string> names,
                                   DiagnosticEmitter& diags);

}  // namespace smachac::refactor
