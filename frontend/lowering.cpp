// The lowering walk (lowering.h): the root, states lists, leaves, containers and inclusions
// with their caller's keys merged, include cycles and depth bounded.
#include "frontend/lowering.h"

#include <fmt/core.h>

#include "frontend/lookups.h"
#include "frontend/resolve_transitions.h"
#include "frontend/root_keys.h"
#include "frontend/shorthand.h"
#include "frontend/standalone_sub_script.h"
#include "frontend/state_builder.h"

namespace smachac::frontend {
namespace {

using ir::StateId;
using ir::Value;

constexpr size_t kMaxContainerDepth = 100;
constexpr size_t kMaxIncludeDepth = 64;

/// "state `NAME`", as messages name a state: made for every state, so by appending (a format
/// call cost about 420 instructions a state).
std::string describeStateName(std::string_view name) {
  std::string what = "state `";
  what.append(name).push_back('`');
  return what;
}

}  // namespace

std::optional<ir::Module> Lowering::run(LoadedYaml loaded) {
  if (!loaded.root) return std::nullopt;
  module_.files().push_back(loaded.file);
  std::vector<ir::Name> output_keys;
  if (sub_script_alone_ && isSubScript(*loaded.root)) {
    StandaloneScript script = standaloneScript(*loaded.root, diags_);
    *loaded.root = std::move(script.root);
    output_keys = std::move(script.output_keys);
  }
  if (!lowerRoot(*loaded.root)) return std::nullopt;
  return finish(std::move(output_keys));
}

bool Lowering::startStreamed(uint32_t file, Value& partial_root) {
  module_.files().push_back(file);
  return buildRoot(partial_root);
}

std::optional<ir::Module> Lowering::finishStreamed(Value& rest_of_states) {
  lowerStates(rest_of_states, module_.root(), root_level_, {});
  return finish({});
}

std::optional<ir::Module> Lowering::finish(std::vector<ir::Name> output_keys) {
  module_.state(module_.root()).output_keys = std::move(output_keys);
  for (uint32_t f : loader_.files()) module_.files().push_back(f);
  resolveTransitions(module_);
  if (diags_.errorCount() > errors_before_ && !keep_module_on_error_) return std::nullopt;
  return std::move(module_);
}

bool Lowering::lowerRoot(Value& root) {
  if (!root.isMap()) {
    SourceLoc where = root.loc.hasFile() ? root.loc : SourceLoc{module_.files()[0], 0, 0, 1};
    diags_.emit<DiagKind::RootNotMapping>(where, describeValue(root));
    if (isSubScript(root)) {
      diags_.note<DiagNoteKind::CompileIncludingScript>(where);
    }
    return false;
  }
  if (!buildRoot(root)) return false;
  lowerStates(*root.find("states"), module_.root(), root_level_, {});
  return true;
}

bool Lowering::buildRoot(Value& root) {
  expandShorthand(root, diags_);
  ir::State state;
  bool complete = buildRootState(root, state, diags_);
  StateId id = module_.addState(std::move(state));
  module_.setRoot(id);
  if (!complete) return false;
  root_level_ = Level{behaviorParams(module_.state(id).params, id)};
  return true;
}

void Lowering::lowerStates(Value& states, StateId parent, Level& level,
                           const std::vector<IncludeFrame>& includes) {
  if (!states.isList()) {
    diags_.emit<DiagKind::InvalidKeyType>(states.loc,
                                          fmt::format("`states` of {}", describeState(parent)),
                                          "a list of states", describeValue(states));
    return;
  }
  for (Value& entry : states.asList()) {
    lowerEntry(entry, parent, level, includes);
    // Nothing reads a lowered state's YAML again: freeing it now lets the next states' IR
    // reuse its memory instead of holding the whole document and the whole IR at once.
    entry = Value();
  }
}

void Lowering::lowerEntry(Value& entry, StateId parent, Level& level,
                          const std::vector<IncludeFrame>& includes) {
  if (entry.isList()) {
    lowerStates(entry, parent, level, includes);
    return;
  }
  if (!entry.isMap() || entry.asMap().size() != 1) {
    std::string found = entry.isMap() ? fmt::format("a mapping of {} keys", entry.asMap().size())
                                      : describeValue(entry);
    diags_.emit<DiagKind::MalformedState>(entry.loc, found);
    return;
  }
  ir::MapEntry& state = entry.asMap().front();
  if (!state.value.isMap()) {
    diags_.emit<DiagKind::InvalidStateBody>(state.value.loc, state.key, describeValue(state.value));
    return;
  }
  expandShorthand(state.value, diags_);
  lowerState({state.key, state.key_loc}, state.value, parent, level, includes, {});
}

std::string Lowering::describeState(StateId id) const {
  const ir::State& s = module_.state(id);
  return s.kind == ir::StateKind::Base ? "the script" : fmt::format("state `{}`", s.name.text);
}

void Lowering::lowerState(const ir::Name& name, Value& vars, StateId parent, Level& level,
                          const std::vector<IncludeFrame>& includes,
                          std::vector<ir::Inclusion> included_from) {
  if (name.text.empty()) diags_.emit<DiagKind::EmptyName>(name.loc, "a state name");
  inheritParams(vars, level.params);
  resolveLookups(vars, diags_);
  if (vars.find("states")) {
    lowerContainer(name, vars, parent, level, includes, std::move(included_from));
  } else if (const Value* script = vars.find("script")) {
    lowerInclude(name, vars, *script, parent, level, includes, std::move(included_from));
  } else {
    lowerLeaf(name, vars, parent, std::move(included_from));
  }
}

StateId Lowering::addState(const ir::Name& name, const Value& vars, ir::StateKind kind,
                           StateId parent, std::vector<ir::Inclusion> included_from) {
  ir::State state;
  state.kind = kind;
  state.name = name;
  state.loc = vars.loc;
  state.included_from = std::move(included_from);
  buildStateFields(vars, state, describeStateName(name.text), diags_);
  StateId id = module_.addState(std::move(state));
  module_.adopt(parent, id);
  return id;
}

void Lowering::lowerLeaf(const ir::Name& name, const Value& vars, StateId parent,
                         std::vector<ir::Inclusion> included_from) {
  StateId id = addState(name, vars, ir::StateKind::Leaf, parent, std::move(included_from));
  if (!module_.state(id).template_name && !vars.find("template")) {
    diags_.emit<DiagKind::MissingKey>(name.loc, fmt::format("state `{}`", name.text), "template");
  }
}

ir::StateKind Lowering::containerKind(const Value& vars) {
  const Value* tmpl = vars.find("template");
  bool concurrence = tmpl && tmpl->isString() && tmpl->asString() == "Concurrence";
  return concurrence ? ir::StateKind::Concurrence : ir::StateKind::StateMachine;
}

void Lowering::lowerContainer(const ir::Name& name, Value& vars, StateId parent, const Level& level,
                              const std::vector<IncludeFrame>& includes,
                              std::vector<ir::Inclusion> included_from) {
  if (vars.find("script")) diags_.emit<DiagKind::StatesWithScript>(name.loc, name.text);
  StateId id = addState(name, vars, containerKind(vars), parent, std::move(included_from));
  if (!module_.state(id).template_name && !vars.find("template")) {
    diags_.emit<DiagKind::MissingKey>(name.loc, fmt::format("container `{}`", name.text),
                                      "template");
  }
  if (level.depth + 1 > kMaxContainerDepth) {
    diags_.emit<DiagKind::NestingTooDeep>(name.loc, kMaxContainerDepth);
    return;
  }
  const ir::State& container = module_.state(id);
  Level child{container.params.copy(), level.depth + 1};
  if (!container.included_from.empty()) child.params = behaviorParams(container.params, id);
  lowerStates(*vars.find("states"), id, child, includes);
}

void Lowering::lowerInclude(const ir::Name& name, Value& vars, const Value& script_value,
                            StateId parent, Level& level, std::vector<IncludeFrame> includes,
                            std::vector<ir::Inclusion> included_from) {
  ir::Name script;
  if (!readName(script_value, fmt::format("`script` of state `{}`", name.text), script, diags_)) {
    return;
  }
  std::optional<SubScriptState> sub = loader_.load(script);
  if (!sub) return;
  if (!enterInclude(script, *sub, includes)) return;
  Value sub_vars = sub->entry.value;
  if (!sub_vars.isMap()) {
    diags_.emit<DiagKind::InvalidStateBody>(sub_vars.loc, sub->entry.key, describeValue(sub_vars));
    return;
  }
  expandShorthand(sub_vars, diags_);
  ir::Inclusion inclusion{sub->file, script, callerKeys(vars), {}};
  if (const Value* own = sub_vars.find("params")) inclusion.script_params = *own;
  mergeCallerKeys(vars, sub_vars, name);
  if (const Value* params = vars.find("params")) level.params = *params;
  included_from.insert(included_from.begin(), std::move(inclusion));
  lowerState(name, sub_vars, parent, level, includes, std::move(included_from));
}

std::vector<ir::Name> Lowering::callerKeys(const Value& caller) {
  std::vector<ir::Name> keys;
  for (const ir::MapEntry& e : caller.asMap()) {
    if (e.key != "script") keys.push_back({e.key, e.key_loc});
  }
  return keys;
}

std::optional<Value> Lowering::behaviorParams(const ir::Boxed<Value>& params, StateId scope) {
  if (!params || !params->isMap()) return params.copy();
  Value marked = *params;
  for (ir::MapEntry& e : marked.asMap()) {
    e.value.behavior_param = module_.addBehaviorParam(scope, e.key);
  }
  return marked;
}

bool Lowering::enterInclude(const ir::Name& script, const SubScriptState& sub,
                            std::vector<IncludeFrame>& includes) {
  std::string display = sources_.path(sub.file);
  for (const IncludeFrame& frame : includes) {
    if (frame.canonical_path != sub.canonical_path) continue;
    std::string chain = sources_.path(module_.files()[0]);
    for (const IncludeFrame& f : includes) chain += " -> " + f.display_path;
    diags_.emit<DiagKind::IncludeCycle>(script.loc, script.text, chain + " -> " + display);
    return false;
  }
  if (includes.size() >= kMaxIncludeDepth) {
    diags_.emit<DiagKind::IncludeTooDeep>(script.loc, kMaxIncludeDepth);
    return false;
  }
  includes.push_back({sub.canonical_path, display});
  return true;
}

void Lowering::mergeCallerKeys(const Value& caller, Value& sub, const ir::Name& name) {
  for (const ir::MapEntry& e : caller.asMap()) {
    if (e.key == "script") continue;
    Value* existing = sub.find(e.key);
    if (existing && existing->isMap() && e.value.isMap()) {
      for (const ir::MapEntry& inner : e.value.asMap()) {
        if (Value* slot = existing->find(inner.key))
          *slot = inner.value;
        else
          existing->asMap().push_back(inner);
      }
    } else if (existing) {
      *existing = e.value;
    } else if (e.key == "userdata" || e.key == "remapping" || e.key == "transitions" ||
               e.key == "autonomy") {
      sub.asMap().push_back(e);
    } else if (e.key != "params") {
      diags_.emit<DiagKind::IgnoredIncludeKey>(e.key_loc, e.key, name.text);
    }
  }
}

std::optional<ir::Module> lowerTree(uint32_t file, Value root, const FrontendOptions& options,
                                    SourceManager& sources, DiagnosticEmitter& diags) {
  Lowering lowering(options, sources, diags);
  std::optional<ir::Module> module = lowering.run({file, std::move(root)});
  if (options.include_sites) *options.include_sites = lowering.includeSites();
  return module;
}

}  // namespace smachac::frontend
