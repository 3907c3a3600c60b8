// IR state → template variables.
#include "backends/generator/state_variables.h"

#include <string>

namespace smachac::generator {
namespace {

void setIfNonEmpty(tmpl::Value& vars, std::string_view key, tmpl::Value value, bool present) {
  if (present) vars.dict().setString(key, std::move(value));
}

tmpl::Value transitionsValue(const ir::State& state) {
  tmpl::Value dict = tmpl::Value::newDict();
  for (const ir::Transition& t : state.transitions) {
    dict.dict().setString(t.outcome.text, tmpl::Value::string(t.target.text));
  }
  return dict;
}

tmpl::Value remappingValue(const ir::State& state) {
  tmpl::Value dict = tmpl::Value::newDict();
  for (const ir::Remap& r : state.remapping) {
    dict.dict().setString(r.key.text, tmpl::Value::string(r.parent_key.text));
  }
  return dict;
}

tmpl::Value argumentsValue(const std::vector<ir::Argument>& args, ValueConverter& converter) {
  tmpl::Value dict = tmpl::Value::newDict();
  for (const ir::Argument& a : args) dict.dict().setString(a.key.text, converter.convert(a.value));
  return dict;
}

tmpl::Value outcomeMapValue(const ir::State& state) {
  tmpl::Value dict = tmpl::Value::newDict();
  for (const ir::OutcomeMapEntry& entry : state.outcome_map) {
    tmpl::Value conditions = tmpl::Value::newDict();
    for (const ir::OutcomeCondition& c : entry.conditions) {
      conditions.dict().setString(c.child.text, tmpl::Value::string(c.child_outcome.text));
    }
    dict.dict().setString(entry.outcome.text, conditions);
  }
  return dict;
}

}  // namespace

void addStateKeys(const ir::State& state, tmpl::Value& vars, ValueConverter& converter) {
  setIfNonEmpty(vars, "outcomes", converter.names(state.outcomes), !state.outcomes.empty());
  setIfNonEmpty(vars, "input_keys", converter.names(state.input_keys), !state.input_keys.empty());
  setIfNonEmpty(vars, "output_keys", converter.names(state.output_keys),
                !state.output_keys.empty());
  setIfNonEmpty(vars, "transitions", transitionsValue(state), !state.transitions.empty());
  setIfNonEmpty(vars, "remapping", remappingValue(state), !state.remapping.empty());
  setIfNonEmpty(vars, "userdata", argumentsValue(state.userdata, converter),
                !state.userdata.empty());
  if (state.params) vars.dict().setString("params", converter.convert(*state.params));
  setIfNonEmpty(vars, "callbacks", argumentsValue(state.callbacks, converter),
                !state.callbacks.empty());
  setIfNonEmpty(vars, "outcome_map", outcomeMapValue(state), !state.outcome_map.empty());
  if (state.default_outcome) {
    vars.dict().setString("default_outcome", tmpl::Value::string(state.default_outcome->text));
  }
  for (const ir::Argument& a : state.args) {
    vars.dict().setString(a.key.text, converter.convert(a.value));
  }
}

tmpl::Value stateVariables(const ir::State& state, std::string_view uuid,
                           ValueConverter& converter) {
  tmpl::Value vars = tmpl::Value::newDict();
  std::string class_name = state.template_name ? state.template_name->text : "";
  vars.dict().setString("class_name", tmpl::Value::string(class_name));
  vars.dict().setString("name", tmpl::Value::string(state.name.text));
  vars.dict().setString("uuid", tmpl::Value::string(std::string(uuid)));
  addStateKeys(state, vars, converter);
  return vars;
}

void updateDict(tmpl::Value& to, const tmpl::Value& from) {
  for (const auto& [key, value] : from.dict().entries()) to.dict().set(key, value);
}

tmpl::Value copyDict(const tmpl::Value& from) {
  tmpl::Value copy = tmpl::Value::newDict();
  updateDict(copy, from);
  return copy;
}

}  // namespace smachac::generator
