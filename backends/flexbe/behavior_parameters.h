// The parameters of a FlexBE behavior: the `params` of the script's root,
// or of the sub-script state an embedded behavior is made of. A key is a parameter when its
// value is text, a number or a boolean (FlexBE's text, numeric and boolean parameter types)
// and its name is a Python identifier that no attribute of flexbe_core's Behavior uses
// (`name`, `node`, `contains`, `create`, ...); any other key stays a value written where a
// lookup uses it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"

namespace smachac::backends::flexbe {

struct BehaviorParameter {
  ir::Name name;
  ir::Value default_value;  ///< without its behavior parameter mark
};

/// Why `key: value` cannot be a behavior parameter ("it is a list", ...), or nullopt.
std::optional<std::string> parameterRejection(std::string_view key, const ir::Value& value);

/// The parameters of the behavior made of `scope`, whose params (after the caller's and the
/// inherited ones were merged in) are `params`; a key's default is its value in `defaults`
/// (a sub-script's own params) when it has one there, else its value in `params`.
std::vector<BehaviorParameter> behaviorParameters(const ir::Value& params,
                                                  const std::optional<ir::Value>& defaults);

/// The script's own parameters; a `params` key that cannot be one is warned about
/// (flexbe-parameter-substituted).
std::vector<BehaviorParameter> scriptParameters(const ir::State& root, DiagnosticEmitter& diags);

/// The references (ir::Value::behavior_param) of `parameters` of the behavior made of `scope`,
/// by reference: what the value converter turns into `self.<name>`.
std::unordered_map<uint32_t, std::string> parameterReferences(
    const ir::Module& module, ir::StateId scope, const std::vector<BehaviorParameter>& parameters);

}  // namespace smachac::backends::flexbe
