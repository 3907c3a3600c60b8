// Typing of core state keys.
#include "frontend/state_builder.h"

#include <fmt/core.h>

#include "ir/python_text.h"

namespace smachac::frontend {
namespace {

using ir::Value;

bool isScalarName(const Value& v) {
  return v.isString() || v.kind() == ir::ValueKind::Int || v.kind() == ir::ValueKind::Bool;
}

std::string field(std::string_view key, std::string_view what) {
  return fmt::format("`{}` of {}", key, what);
}

/// readName's usual case, a non-empty string, without formatting the message it might need.
bool readStringName(const Value& v, ir::Name& out) {
  if (!v.isString() || v.asString().empty()) return false;
  out.text = v.asString();
  out.loc = v.loc;
  return true;
}

void readNameList(const Value& v, std::string_view key, std::string_view what,
                  std::vector<ir::Name>& out, DiagnosticEmitter& diags) {
  if (!v.isList()) {
    diags.emit<DiagKind::InvalidKeyType>(v.loc, field(key, what), "a list of names",
                                         describeValue(v));
    return;
  }
  out.reserve(out.size() + v.asList().size());
  for (const Value& item : v.asList()) {
    ir::Name name;
    if (readStringName(item, name) || readName(item, field(key, what) + " entries", name, diags)) {
      out.push_back(std::move(name));
    }
  }
}

/// Calls `each(entry)` for each entry of a mapping, or reports the key as not a mapping. A
/// template rather than a std::function: the callers' lambdas would not fit its small buffer
/// and cost an allocation per call.
template <typename Each>
bool forEachEntry(const Value& v, std::string_view key, std::string_view what,
                  std::string_view expected, const Each& each, DiagnosticEmitter& diags) {
  if (!v.isMap()) {
    diags.emit<DiagKind::InvalidKeyType>(v.loc, field(key, what), expected, describeValue(v));
    return false;
  }
  for (const ir::MapEntry& entry : v.asMap()) each(entry);
  return true;
}

ir::Name keyName(const ir::MapEntry& entry) { return {entry.key, entry.key_loc}; }

void readTransitions(const Value& v, std::string_view what, ir::State& state,
                     DiagnosticEmitter& diags) {
  if (v.isMap()) state.transitions.reserve(state.transitions.size() + v.asMap().size());
  forEachEntry(
      v, "transitions", what, "a mapping from outcome to target",
      [&](const ir::MapEntry& e) {
        ir::Name target;
        if (readStringName(e.value, target) ||
            readName(e.value, field("transitions", what) + " targets", target, diags)) {
          state.transitions.push_back(
              {keyName(e), std::move(target), ir::TargetKind::Unresolved, {}});
        }
      },
      diags);
}

void readRemapping(const Value& v, std::string_view what, ir::State& state,
                   DiagnosticEmitter& diags) {
  forEachEntry(
      v, "remapping", what, "a mapping from state key to parent key",
      [&](const ir::MapEntry& e) {
        ir::Name parent;
        if (readStringName(e.value, parent) ||
            readName(e.value, field("remapping", what) + " values", parent, diags)) {
          state.remapping.push_back({keyName(e), parent});
        }
      },
      diags);
}

void readArguments(const Value& v, std::string_view key, std::string_view what,
                   std::vector<ir::Argument>& out, DiagnosticEmitter& diags) {
  forEachEntry(
      v, key, what, "a mapping",
      [&](const ir::MapEntry& e) {
        out.push_back({keyName(e), e.value});
      },
      diags);
}

void readOutcomeMap(const Value& v, std::string_view what, ir::State& state,
                    DiagnosticEmitter& diags) {
  std::string inner_what = field("outcome_map", what) + " entries";
  forEachEntry(
      v, "outcome_map", what, "a mapping from outcome to {child: outcome}",
      [&](const ir::MapEntry& e) {
        ir::OutcomeMapEntry entry{keyName(e), {}};
        if (!e.value.isMap()) {
          diags.emit<DiagKind::InvalidKeyType>(e.value.loc, inner_what,
                                               "a mapping from child state to its outcome",
                                               describeValue(e.value));
          return;
        }
        for (const ir::MapEntry& c : e.value.asMap()) {
          ir::Name outcome;
          if (readName(c.value, inner_what, outcome, diags)) {
            entry.conditions.push_back({keyName(c), outcome});
          }
        }
        state.outcome_map.push_back(std::move(entry));
      },
      diags);
}

bool readCoreKey(const ir::MapEntry& e, std::string_view what, ir::State& state,
                 DiagnosticEmitter& diags) {
  const std::string& key = e.key;
  const Value& v = e.value;
  if (key == "template") {
    ir::Name name;
    if (readStringName(v, name) || readName(v, field(key, what), name, diags)) {
      state.template_name = std::move(name);
    }
  } else if (key == "outcomes") {
    readNameList(v, key, what, state.outcomes, diags);
  } else if (key == "input_keys") {
    readNameList(v, key, what, state.input_keys, diags);
  } else if (key == "output_keys") {
    readNameList(v, key, what, state.output_keys, diags);
  } else if (key == "transitions") {
    readTransitions(v, what, state, diags);
  } else if (key == "remapping") {
    readRemapping(v, what, state, diags);
  } else if (key == "userdata") {
    readArguments(v, key, what, state.userdata, diags);
  } else if (key == "callbacks") {
    readArguments(v, key, what, state.callbacks, diags);
  } else if (key == "outcome_map") {
    readOutcomeMap(v, what, state, diags);
  } else if (key == "params") {
    if (v.isMap())
      state.params = v;
    else
      diags.emit<DiagKind::InvalidKeyType>(v.loc, field(key, what), "a mapping", describeValue(v));
  } else if (key == "default_outcome") {
    ir::Name name;
    if (readName(v, field(key, what), name, diags)) state.default_outcome = name;
  } else {
    return key == "states" || key == "script";
  }
  return true;
}

}  // namespace

bool readName(const Value& value, std::string_view what, ir::Name& out, DiagnosticEmitter& diags) {
  if (!isScalarName(value)) {
    diags.emit<DiagKind::InvalidKeyType>(value.loc, what, "a name", describeValue(value));
    return false;
  }
  out = {value.isString() ? value.asString() : ir::pythonStr(value), value.loc};
  if (out.text.empty()) {
    diags.emit<DiagKind::EmptyName>(value.loc, what);
    return false;
  }
  return true;
}

void buildStateFields(const Value& vars, ir::State& state, std::string_view what,
                      DiagnosticEmitter& diags) {
  for (const ir::MapEntry& e : vars.asMap()) {
    if (!readCoreKey(e, what, state, diags)) state.args.push_back({keyName(e), e.value});
  }
}

}  // namespace smachac::frontend
