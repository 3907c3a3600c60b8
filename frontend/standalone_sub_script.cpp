// The stand-in script of a sub-script linted on its own.
#include "frontend/standalone_sub_script.h"

#include <string>

#include "frontend/shorthand.h"

namespace smachac::frontend {
namespace {

using ir::Value;

/// The names of a list of strings (other entries are left to the state's own checks).
std::vector<ir::Name> namesIn(const Value* list) {
  std::vector<ir::Name> names;
  if (!list || !list->isList()) return names;
  for (const Value& item : list->asList()) {
    if (item.isString()) names.push_back({item.asString(), item.loc});
  }
  return names;
}

/// `key` as the caller's scope knows it: through the state's remapping.
ir::Name remapped(const Value& body, const ir::Name& key) {
  const Value* remapping = body.find("remapping");
  const Value* target = remapping && remapping->isMap() ? remapping->find(key.text) : nullptr;
  if (target && target->isString()) return {target->asString(), target->loc};
  return key;
}

ir::MapEntry entry(std::string key, Value value) {
  SourceLoc loc = value.loc;
  return {std::move(key), loc, std::move(value)};
}

/// The script's userdata: each key the state reads, as null.
Value callerUserdata(const Value& body) {
  Value userdata = Value::map({}, body.loc);
  for (const ir::Name& key : namesIn(body.find("input_keys"))) {
    ir::Name name = remapped(body, key);
    if (!userdata.find(name.text)) {
      userdata.asMap().push_back({name.text, name.loc, Value::null(name.loc)});
    }
  }
  return userdata;
}

/// The param `x` of a lookup `[params, x]` or `[[x]]`, if `v` is one.
const Value* lookedUpParam(const Value& v) {
  if (!v.isList()) return nullptr;
  const ir::List& items = v.asList();
  if (items.size() == 2 && items[0].isString() && items[0].asString() == "params" &&
      items[1].isString()) {
    return &items[1];
  }
  bool nested = items.size() == 1 && items[0].isList() && items[0].asList().size() == 1;
  if (nested && items[0].asList()[0].isString()) return &items[0].asList()[0];
  return nullptr;
}

/// Adds, as null, each param that a lookup in `v` reads to `params`.
void addLookedUpParams(const Value& v, Value& params) {
  if (const Value* name = lookedUpParam(v)) {
    if (!params.find(name->asString())) {
      params.asMap().push_back({name->asString(), name->loc, Value::null(name->loc)});
    }
  } else if (v.isList()) {
    for (const Value& item : v.asList()) addLookedUpParams(item, params);
  } else if (v.isMap()) {
    for (const ir::MapEntry& e : v.asMap()) addLookedUpParams(e.value, params);
  }
}

}  // namespace

bool isSubScript(const ir::Value& root) {
  if (!root.isList() || root.asList().size() != 1) return false;
  const Value& state = root.asList().front();
  return state.isMap() && state.asMap().size() == 1 && state.asMap().front().value.isMap();
}

StandaloneScript standaloneScript(const ir::Value& root, DiagnosticEmitter& diags) {
  ir::MapEntry state = root.asList().front().asMap().front();
  expandShorthand(state.value, diags);
  Value& body = state.value;
  std::erase_if(body.asMap(), [](const ir::MapEntry& e) { return e.key == "transitions"; });
  StandaloneScript script{Value::map({}, root.loc), {}};
  for (const ir::Name& key : namesIn(body.find("output_keys"))) {
    script.output_keys.push_back(remapped(body, key));
  }
  ir::Map& keys = script.root.asMap();
  keys.push_back(entry("name", Value::string(state.key, state.key_loc)));
  keys.push_back(entry("template", Value::string("Base", root.loc)));
  const Value* outcomes = body.find("outcomes");
  keys.push_back(entry("outcomes", outcomes ? *outcomes : Value::list({}, root.loc)));
  keys.push_back(entry("userdata", callerUserdata(body)));
  Value params = Value::map({}, root.loc);
  addLookedUpParams(body, params);
  keys.push_back(entry("params", std::move(params)));
  keys.push_back(
      entry("states", Value::list({Value::map({std::move(state)}, root.loc)}, root.loc)));
  return script;
}

}  // namespace smachac::frontend
