// Sub-scripts as embedded FlexBE behaviors: a StateMachine included from a
// sub-script becomes a behavior of its own, which the including behavior declares in
// `__init__` (`self.add_behavior(XSM, 'path')`) and adds with
// `self.use_behavior(XSM, 'path', parameters={...})`. That is possible when the including
// state sets only what FlexBE can pass to a behavior or what belongs to the including level:
// `params`, `transitions`, `remapping` and `autonomy`. A sub-script state that is a leaf or a
// Concurrence, or whose caller sets other keys (its userdata, outcomes, keys, ...), is inlined
// as before.
//
// The functions below restructure the FlexBE target's working copy of the module: the
// included state's contents move to a new Base root (the embedded behavior's module is that
// root's subtree), and the state itself becomes a leaf of template EmbeddedBehavior.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"

namespace smachac::backends::flexbe {

/// The included StateMachines of `module` that become embedded behaviors, every one after
/// the ones inside it, siblings in script order. Included StateMachines whose caller sets a
/// key FlexBE cannot pass are warned about (flexbe-inlined-sub-script) and left out.
std::vector<ir::StateId> embeddedStates(const ir::Module& module, DiagnosticEmitter& diags);

/// The path of `state` in the behavior it belongs to: the labels below the nearest ancestor
/// that is in `behavior_roots` (or below the module's root), joined by '/'.
std::string behaviorPath(const ir::Module& module, ir::StateId state,
                         const std::set<ir::StateId>& behavior_roots);

/// Moves the children, outcomes, userdata keys and defaults of `state` to a new, unattached
/// Base state named `name` with template `base_template`; returns it.
ir::StateId detachBehavior(ir::Module& module, ir::StateId state, const std::string& name,
                           const ir::Name& base_template);

/// Turns `state` into a leaf of template EmbeddedBehavior that uses behavior `name` as `id`,
/// passing `parameters` (a map); it keeps its transitions, remapping and autonomy.
void useBehavior(ir::Module& module, ir::StateId state, const std::string& name,
                 const std::string& id, ir::Value parameters);

/// The behaviors that the EmbeddedBehavior leaves below `root` use: {name, id} pairs in
/// script order.
std::vector<std::pair<std::string, std::string>> usedBehaviors(const ir::Module& module,
                                                               ir::StateId root);

}  // namespace smachac::backends::flexbe
