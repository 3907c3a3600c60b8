// The walk that lowers one script's YAML tree into an ir::Module: the root, states,
// containers and sub-script inclusions, in document order, every error reported and the walk
// going on after it. `lowerTree` lowers a whole tree; streamed_lowering.h feeds the walk the
// root's states one at a time while the file is still being read. Internal to the frontend.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "frontend/lower.h"
#include "frontend/sub_scripts.h"
#include "frontend/yaml_loader.h"

namespace smachac::frontend {

class Lowering {
  using StateId = ir::StateId;
  using Value = ir::Value;

 public:
  Lowering(const FrontendOptions& options, SourceManager& sources, DiagnosticEmitter& diags)
      : sub_script_alone_(options.sub_script_alone),
        keep_module_on_error_(options.keep_module_on_error),
        sources_(sources),
        diags_(diags),
        loader_(options.script_dirs, options.overlay, sources, diags),
        errors_before_(diags.errorCount()) {}

  std::optional<ir::Module> run(LoadedYaml loaded);

  /// Streamed lowering (streamed_lowering.h): the root state from the root's keys before
  /// `states` (and an empty `states`); false when it is incomplete and no state may follow.
  bool startStreamed(uint32_t file, Value& partial_root);

  /// Streamed lowering: one item of the root's `states`, as the reader completes it.
  void lowerRootEntry(Value& entry) { lowerEntry(entry, module_.root(), root_level_, {}); }

  /// Streamed lowering: the items the reader left in the tree, then the module.
  std::optional<ir::Module> finishStreamed(Value& rest_of_states);

  const IncludeSites& includeSites() const { return loader_.includeSites(); }

 private:
  /// What a level of the script (the root or a container's children) passes to its states.
  struct Level {
    std::optional<Value> params;
    size_t depth = 0;
  };

  /// One active inclusion, for cycle detection and provenance.
  struct IncludeFrame {
    std::string canonical_path;
    std::string display_path;
  };

  std::optional<ir::Module> finish(std::vector<ir::Name> output_keys);

  bool lowerRoot(Value& root);

  /// The root state and what the root level passes to its states; false when incomplete.
  bool buildRoot(Value& root);

  /// states ::= [ {NAME: {...}} | [states...] ... ]
  void lowerStates(Value& states, StateId parent, Level& level,
                   const std::vector<IncludeFrame>& includes);

  /// One item of a `states` list: a state, or a nested list of them.
  void lowerEntry(Value& entry, StateId parent, Level& level,
                  const std::vector<IncludeFrame>& includes);

  std::string describeState(StateId id) const;

  void lowerState(const ir::Name& name, Value& vars, StateId parent, Level& level,
                  const std::vector<IncludeFrame>& includes,
                  std::vector<ir::Inclusion> included_from);

  StateId addState(const ir::Name& name, const Value& vars, ir::StateKind kind, StateId parent,
                   std::vector<ir::Inclusion> included_from);

  void lowerLeaf(const ir::Name& name, const Value& vars, StateId parent,
                 std::vector<ir::Inclusion> included_from);

  static ir::StateKind containerKind(const Value& vars);

  void lowerContainer(const ir::Name& name, Value& vars, StateId parent, const Level& level,
                      const std::vector<IncludeFrame>& includes,
                      std::vector<ir::Inclusion> included_from);

  void lowerInclude(const ir::Name& name, Value& vars, const Value& script_value, StateId parent,
                    Level& level, std::vector<IncludeFrame> includes,
                    std::vector<ir::Inclusion> included_from);

  /// The keys the including state sets besides `script`.
  static std::vector<ir::Name> callerKeys(const Value& caller);

  /// The params of a behavior's root (the script's or a sub-script state's) as its children
  /// inherit them: each value marked as that behavior's parameter.
  std::optional<Value> behaviorParams(const ir::Boxed<Value>& params, StateId scope);

  /// Cycle and depth checks; pushes the sub-script on `includes`.
  bool enterInclude(const ir::Name& script, const SubScriptState& sub,
                    std::vector<IncludeFrame>& includes);

  /// The caller's keys override the sub-script state's: mappings are merged (the caller's
  /// entries win), other values replace; userdata, remapping, transitions and autonomy (the
  /// FlexBE target's) are added when the sub-script has none. `script` and `params` are
  /// consumed by the inclusion itself.
  void mergeCallerKeys(const Value& caller, Value& sub, const ir::Name& name);

  bool sub_script_alone_;
  bool keep_module_on_error_;
  SourceManager& sources_;
  DiagnosticEmitter& diags_;
  SubScriptLoader loader_;
  size_t errors_before_;  ///< errors of earlier scripts (lint checks several in one session)
  ir::Module module_;
  Level root_level_;
};

/// The classic way: the whole tree of the script registered as `file`, then lowering.
std::optional<ir::Module> lowerTree(uint32_t file, ir::Value root, const FrontendOptions& options,
                                    SourceManager& sources, DiagnosticEmitter& diags);

}  // namespace smachac::frontend
