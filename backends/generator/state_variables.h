// The view model: what a template sees of an IR state.
//   class_name  the state's template name as written in the script
//   name        the state's name;   uuid  its id (see state_uuid.h)
//   outcomes, input_keys, output_keys             lists of names
//   transitions, remapping                        {outcome: target}, {state_key: parent_key}
//   userdata, callbacks, params                   dicts of values (callbacks keep backticks)
//   outcome_map, default_outcome                  {outcome: {child: outcome}}, a name
//   every other script key                        its value, in script order
// Keys the script does not give are absent (templates test them with `is defined`); an empty
// list or mapping is indistinguishable from an absent one in the IR and is left out too. Later
// keys win, so a script key `name` overrides the state's name, as in SMACHA.
#pragma once

#include <string_view>

#include "backends/generator/template_values.h"
#include "backends/tmpl/values/value.h"
#include "ir/state.h"

namespace smachac::generator {

/// The template variables of `state`: class_name, name and uuid, then its keys (without
/// `template`, `states` or `script`).
tmpl::Value stateVariables(const ir::State& state, std::string_view uuid,
                           ValueConverter& converter);

/// Adds the state's script keys to `vars` (a dict).
void addStateKeys(const ir::State& state, tmpl::Value& vars, ValueConverter& converter);

/// Sets every entry of `from` (a dict) in `to` (a dict), replacing same-named entries.
void updateDict(tmpl::Value& to, const tmpl::Value& from);

/// A new dict with the entries of `from` (the values are shared, as Python's dict.copy()).
tmpl::Value copyDict(const tmpl::Value& from);

}  // namespace smachac::generator
