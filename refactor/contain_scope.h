// What every step of `contain` shares: the request, the script, the selected run of root
// states, and the edits being collected on the script's text.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ir/state_kind.h"
#include "ir/support/diagnostic_emitter.h"
#include "refactor/map_edits.h"
#include "refactor/script_view.h"
#include "refactor/selection.h"

namespace smachac::refactor {

struct ContainRequest {
  std::string name;                                  ///< the new container's name
  ir::StateKind kind = ir::StateKind::StateMachine;  ///< StateMachine or Concurrence
  std::vector<std::string> states;                   ///< the root states to contain, in order
  std::optional<std::string> default_target;  ///< Concurrence: where the default outcome goes
};

struct ContainScope {
  const ScriptView& script;
  const ContainRequest& request;
  Selection selection;
  EditList& edits;
  EntryDeletions& deletions;  ///< applied once all steps have run
  DiagnosticEmitter& diags;

  const SourceText& text() const { return script.text(); }
  MapEditor maps() const { return {script.text(), edits}; }
  const RootState& root(size_t index) const { return script.states()[index]; }
  const ir::State& state(size_t index) const { return script.state(index); }
  bool concurrence() const { return request.kind == ir::StateKind::Concurrence; }

  /// The root index of a selected state named `name`.
  std::optional<size_t> selectedIndex(std::string_view name) const {
    for (size_t i = selection.first; i <= selection.last(); ++i) {
      if (root(i).name() == name) return i;
    }
    return std::nullopt;
  }
};

}  // namespace smachac::refactor
