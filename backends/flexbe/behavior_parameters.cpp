// Which params of a behavior's root are FlexBE behavior parameters, and their defaults.
#include "backends/flexbe/behavior_parameters.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>

#include "ir/support/identifiers.h"

namespace smachac::backends::flexbe {
namespace {

/// Attributes and methods of flexbe_core's Behavior (ROS 1 and ROS 2) that a parameter, set
/// with setattr, would overwrite.
constexpr std::array<std::string_view, 20> kBehaviorAttributes = {"add_behavior",
                                                                  "add_parameter",
                                                                  "beh_id",
                                                                  "confirm",
                                                                  "contains",
                                                                  "create",
                                                                  "execute",
                                                                  "get_contained_behaviors",
                                                                  "get_current_states",
                                                                  "get_latest_status",
                                                                  "get_locked_state",
                                                                  "name",
                                                                  "node",
                                                                  "preempt",
                                                                  "prepare_for_execution",
                                                                  "prepare_for_switch",
                                                                  "requested_state_path",
                                                                  "set_parameter",
                                                                  "set_up",
                                                                  "use_behavior"};

bool isParameterValue(const ir::Value& value) {
  switch (value.kind()) {
    case ir::ValueKind::Bool:
    case ir::ValueKind::Int:
    case ir::ValueKind::Float:
    case ir::ValueKind::String:
      return true;
    default:
      return false;
  }
}

ir::Value unmarked(ir::Value value) {
  value.behavior_param = 0;
  return value;
}

}  // namespace

std::optional<std::string> parameterRejection(std::string_view key, const ir::Value& value) {
  if (std::optional<std::string> problem = identifierProblem(key, IdentifierRules::Python)) {
    return fmt::format("its name {}", *problem);
  }
  if (key.starts_with('_')) return std::string("names starting with `_` are the Behavior's own");
  if (std::find(kBehaviorAttributes.begin(), kBehaviorAttributes.end(), key) !=
      kBehaviorAttributes.end()) {
    return fmt::format("FlexBE's Behavior has an attribute `{}`", key);
  }
  if (value.kind() == ir::ValueKind::Expression) return std::string("its value is an expression");
  if (!isParameterValue(value)) {
    return fmt::format("FlexBE parameters are text, numbers or booleans, not {}",
                       describeValue(value));
  }
  return std::nullopt;
}

std::vector<BehaviorParameter> behaviorParameters(const ir::Value& params,
                                                  const std::optional<ir::Value>& defaults) {
  std::vector<BehaviorParameter> parameters;
  if (!params.isMap()) return parameters;
  for (const ir::MapEntry& entry : params.asMap()) {
    const ir::Value* own = defaults ? defaults->find(entry.key) : nullptr;
    const ir::Value& value = own ? *own : entry.value;
    if (parameterRejection(entry.key, value)) continue;
    parameters.push_back({{entry.key, entry.key_loc}, unmarked(value)});
  }
  return parameters;
}

std::vector<BehaviorParameter> scriptParameters(const ir::State& root, DiagnosticEmitter& diags) {
  if (!root.params || !root.params->isMap()) return {};
  for (const ir::MapEntry& entry : root.params->asMap()) {
    if (std::optional<std::string> why = parameterRejection(entry.key, entry.value)) {
      diags.emit<DiagKind::FlexbeParameterSubstituted>(entry.key_loc, entry.key, *why);
    }
  }
  return behaviorParameters(*root.params, std::nullopt);
}

std::unordered_map<uint32_t, std::string> parameterReferences(
    const ir::Module& module, ir::StateId scope, const std::vector<BehaviorParameter>& parameters) {
  std::unordered_map<uint32_t, std::string> refs;
  for (const BehaviorParameter& parameter : parameters) {
    if (uint32_t ref = module.findBehaviorParam(scope, parameter.name.text)) {
      refs.emplace(ref, parameter.name.text);
    }
  }
  return refs;
}

}  // namespace smachac::backends::flexbe
