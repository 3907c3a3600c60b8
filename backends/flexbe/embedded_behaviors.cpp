// Restructuring of included StateMachines into embedded behaviors.
#include "backends/flexbe/embedded_behaviors.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace smachac::backends::flexbe {
namespace {

constexpr std::string_view kLeafTemplate = "EmbeddedBehavior";

/// What an including state may set for its sub-script to stay an embedded behavior.
constexpr std::array<std::string_view, 4> kPassableKeys = {"params", "transitions", "remapping",
                                                           "autonomy"};

const ir::Name* unpassableKey(const ir::Inclusion& inclusion) {
  for (const ir::Name& key : inclusion.caller_keys) {
    if (std::find(kPassableKeys.begin(), kPassableKeys.end(), key.text) == kPassableKeys.end()) {
      return &key;
    }
  }
  return nullptr;
}

void collect(const ir::Module& module, ir::StateId id, DiagnosticEmitter& diags,
             std::vector<ir::StateId>& out) {
  const ir::State& state = module.state(id);
  for (ir::StateId child : state.children) collect(module, child, diags, out);
  if (state.included_from.empty() || state.kind != ir::StateKind::StateMachine) return;
  const ir::Inclusion& inclusion = state.included_from.front();
  if (const ir::Name* key = unpassableKey(inclusion)) {
    diags.emit<DiagKind::FlexbeInlinedSubScript>(key->loc, inclusion.script.text, key->text);
    return;
  }
  out.push_back(id);
}

ir::Argument argument(std::string key, ir::Value value) {
  return {{std::move(key), {}}, std::move(value)};
}

}  // namespace

std::vector<ir::StateId> embeddedStates(const ir::Module& module, DiagnosticEmitter& diags) {
  std::vector<ir::StateId> states;
  for (ir::StateId child : module.state(module.root()).children) {
    collect(module, child, diags, states);
  }
  return states;
}

std::string behaviorPath(const ir::Module& module, ir::StateId state,
                         const std::set<ir::StateId>& behavior_roots) {
  std::string path = module.state(state).name.text;
  for (ir::StateId p = module.state(state).parent;
       p.valid() && p != module.root() && !behavior_roots.count(p); p = module.state(p).parent) {
    path = module.state(p).name.text + "/" + path;
  }
  return path;
}

ir::StateId detachBehavior(ir::Module& module, ir::StateId state, const std::string& name,
                           const ir::Name& base_template) {
  ir::State root;
  root.kind = ir::StateKind::Base;
  ir::State& from = module.state(state);
  root.name = {name, from.name.loc};
  root.loc = from.loc;
  root.template_name = base_template;
  root.outcomes = from.outcomes;
  root.input_keys = from.input_keys;
  root.output_keys = from.output_keys;
  root.userdata = std::move(from.userdata);
  root.children = std::move(from.children);
  from.userdata.clear();
  from.children.clear();
  ir::StateId id = module.addState(std::move(root));
  for (ir::StateId child : module.state(id).children) module.state(child).parent = id;
  return id;
}

void useBehavior(ir::Module& module, ir::StateId state, const std::string& name,
                 const std::string& id, ir::Value parameters) {
  ir::State& leaf = module.state(state);
  leaf.kind = ir::StateKind::Leaf;
  SourceLoc where = leaf.template_name ? leaf.template_name->loc : leaf.name.loc;
  leaf.template_name = ir::Name{std::string(kLeafTemplate), where};
  std::vector<ir::Argument> args;
  if (const ir::Argument* autonomy = leaf.findArg("autonomy")) args.push_back(*autonomy);
  args.push_back(argument("behavior_name", ir::Value::string(name)));
  args.push_back(argument("behavior_id", ir::Value::string(id)));
  args.push_back(argument("behavior_parameters", std::move(parameters)));
  leaf.args = std::move(args);
  leaf.callbacks.clear();
}

std::vector<std::pair<std::string, std::string>> usedBehaviors(const ir::Module& module,
                                                               ir::StateId root) {
  std::vector<std::pair<std::string, std::string>> used;
  std::vector<ir::StateId> stack{root};
  while (!stack.empty()) {
    const ir::State& state = module.state(stack.back());
    stack.pop_back();
    for (auto it = state.children.rbegin(); it != state.children.rend(); ++it) {
      stack.push_back(*it);
    }
    if (state.kind != ir::StateKind::Leaf || !state.template_name ||
        state.template_name->text != kLeafTemplate) {
      continue;
    }
    const ir::Argument* name = state.findArg("behavior_name");
    const ir::Argument* id = state.findArg("behavior_id");
    if (name && id && name->value.isString() && id->value.isString()) {
      used.emplace_back(name->value.asString(), id->value.asString());
    }
  }
  return used;
}

}  // namespace smachac::backends::flexbe
