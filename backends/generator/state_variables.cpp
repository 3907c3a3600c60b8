// IR state → template variables.
#include "backends/generator/state_variables.h"

#include <string>

namespace smachac::generator {
namespace {

/// Entries a state's variables make room for at once: its own (at most 13 besides its script
/// keys) and those of its level that the generator adds (parent names, the base's exports).
constexpr size_t kStateVariablesRoom = 24;

tmpl::Value transitionsValue(const ir::State& state, ValueConverter& converter) {
  tmpl::Value dict = tmpl::Value::newDict();
  for (const ir::Transition& t : state.transitions) {
    dict.dict().set(converter.text(t.outcome.text), converter.text(t.target.text));
  }
  return dict;
}

tmpl::Value remappingValue(const ir::State& state, ValueConverter& converter) {
  tmpl::Value dict = tmpl::Value::newDict();
  for (const ir::Remap& r : state.remapping) {
    dict.dict().setString(r.key.text, converter.text(r.parent_key.text));
  }
  return dict;
}

tmpl::Value argumentsValue(const std::vector<ir::Argument>& args, ValueConverter& converter) {
  tmpl::Value dict = tmpl::Value::newDict();
  for (const ir::Argument& a : args) dict.dict().setString(a.key.text, converter.convert(a.value));
  return dict;
}

tmpl::Value outcomeMapValue(const ir::State& state, ValueConverter& converter) {
  tmpl::Value dict = tmpl::Value::newDict();
  for (const ir::OutcomeMapEntry& entry : state.outcome_map) {
    tmpl::Value conditions = tmpl::Value::newDict();
    for (const ir::OutcomeCondition& c : entry.conditions) {
      conditions.dict().setString(c.child.text, converter.text(c.child_outcome.text));
    }
    dict.dict().setString(entry.outcome.text, conditions);
  }
  return dict;
}

}  // namespace

void addStateKeys(const ir::State& state, tmpl::Value& vars, ValueConverter& converter) {
  tmpl::DictObject& dict = vars.dict();
  auto set = [&](const tmpl::Value& key, tmpl::Value value) { dict.set(key, std::move(value)); };
  if (!state.outcomes.empty()) set(converter.literal("outcomes"), converter.names(state.outcomes));
  if (!state.input_keys.empty()) {
    set(converter.literal("input_keys"), converter.names(state.input_keys));
  }
  if (!state.output_keys.empty()) {
    set(converter.literal("output_keys"), converter.names(state.output_keys));
  }
  if (!state.transitions.empty()) {
    set(converter.literal("transitions"), transitionsValue(state, converter));
  }
  if (!state.remapping.empty()) {
    set(converter.literal("remapping"), remappingValue(state, converter));
  }
  if (!state.userdata.empty()) {
    set(converter.literal("userdata"), argumentsValue(state.userdata, converter));
  }
  if (state.params) set(converter.literal("params"), converter.convert(*state.params));
  if (!state.callbacks.empty()) {
    set(converter.literal("callbacks"), argumentsValue(state.callbacks, converter));
  }
  if (!state.outcome_map.empty()) {
    set(converter.literal("outcome_map"), outcomeMapValue(state, converter));
  }
  if (state.default_outcome) {
    set(converter.literal("default_outcome"), converter.text(state.default_outcome->text));
  }
  for (const ir::Argument& a : state.args) dict.setString(a.key.text, converter.convert(a.value));
}

tmpl::Value stateVariables(const ir::State& state, std::string_view uuid,
                           ValueConverter& converter) {
  tmpl::Value vars = tmpl::Value::newDict();
  vars.dict().reserve(kStateVariablesRoom);
  vars.dict().set(converter.literal("class_name"), state.template_name
                                                       ? converter.text(state.template_name->text)
                                                       : tmpl::Value::string(std::string()));
  vars.dict().set(converter.literal("name"), tmpl::Value::string(state.name.text));
  vars.dict().set(converter.literal("uuid"), tmpl::Value::string(std::string(uuid)));
  addStateKeys(state, vars, converter);
  return vars;
}

void updateDict(tmpl::Value& to, const tmpl::Value& from) { to.dict().update(from.dict()); }

tmpl::Value copyDict(const tmpl::Value& from) {
  tmpl::Value copy = tmpl::Value::newDict();
  updateDict(copy, from);
  return copy;
}

}  // namespace smachac::generator
