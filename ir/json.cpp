// IR → JSON.
#include "ir/json.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "ir/support/python_float.h"
#include "ir/type.h"

namespace smachac::ir {
namespace {

using Json = nlohmann::ordered_json;

class JsonWriter {
 public:
  JsonWriter(const Module& module, const SourceManager& sources)
      : module_(module), sources_(sources) {}

  Json run() {
    Json files = Json::array();
    for (uint32_t f : module_.files()) files.push_back(sources_.path(f));
    Json doc = {{"format", "smachac-ir"}, {"version", 1}, {"files", files}};
    doc["root"] = module_.root().valid() ? state(module_.root()) : Json(nullptr);
    return doc;
  }

 private:
  Json loc(SourceLoc l) const {
    const std::vector<uint32_t>& files = module_.files();
    auto it = std::find(files.begin(), files.end(), l.file);
    Json file = it == files.end() ? Json(nullptr) : Json(it - files.begin());
    return {{"file", file}, {"line", l.line}, {"column", l.column}};
  }

  Json name(const Name& n) const { return {{"text", n.text}, {"loc", loc(n.loc)}}; }

  Json names(const std::vector<Name>& list) const {
    Json out = Json::array();
    for (const Name& n : list) out.push_back(name(n));
    return out;
  }

  static Json plain(const Value& v) {
    switch (v.kind()) {
      case ValueKind::Null:
        return nullptr;
      case ValueKind::Bool:
        return v.asBool();
      case ValueKind::Int:
        return v.asInt();
      case ValueKind::Float:
        if (std::isfinite(v.asFloat())) return v.asFloat();
        return {{"float", pythonFloatRepr(v.asFloat())}};
      case ValueKind::String:
        return v.asString();
      case ValueKind::Expression:
        if (v.asPortable()) return {{"portable_expression", v.asExpression().code}};
        return {{"expression", v.asExpression().code}};
      case ValueKind::List: {
        Json out = Json::array();
        for (const Value& item : v.asList()) out.push_back(plain(item));
        return out;
      }
      case ValueKind::Map: {
        Json out = Json::object();
        for (const MapEntry& e : v.asMap()) out[e.key] = plain(e.value);
        return out;
      }
    }
    return nullptr;
  }

  Json value(const Value& v) const {
    Json out = {{"type", Type::ofValue(v).str()}, {"value", plain(v)}, {"loc", loc(v.loc)}};
    if (v.forced_string) out["forced_string"] = true;
    return out;
  }

  Json arguments(const std::vector<Argument>& args) const {
    Json out = Json::array();
    for (const Argument& a : args) out.push_back({{"key", name(a.key)}, {"value", value(a.value)}});
    return out;
  }

  void addEdges(Json& j, const State& s) const {
    if (!s.transitions.empty()) {
      Json list = Json::array();
      for (const Transition& t : s.transitions) {
        list.push_back({{"outcome", name(t.outcome)},
                        {"target", name(t.target)},
                        {"target_kind", targetKindName(t.target_kind)}});
      }
      j["transitions"] = list;
    }
    if (!s.remapping.empty()) {
      Json list = Json::array();
      for (const Remap& r : s.remapping) {
        list.push_back({{"key", name(r.key)}, {"parent_key", name(r.parent_key)}});
      }
      j["remapping"] = list;
    }
    if (!s.outcome_map.empty()) {
      Json list = Json::array();
      for (const OutcomeMapEntry& e : s.outcome_map) {
        Json conditions = Json::array();
        for (const OutcomeCondition& c : e.conditions) {
          conditions.push_back({{"child", name(c.child)}, {"outcome", name(c.child_outcome)}});
        }
        list.push_back({{"outcome", name(e.outcome)}, {"conditions", conditions}});
      }
      j["outcome_map"] = list;
    }
  }

  void addFields(Json& j, const State& s) const {
    if (s.template_name) j["template"] = name(*s.template_name);
    if (!s.outcomes.empty()) j["outcomes"] = names(s.outcomes);
    if (!s.input_keys.empty()) j["input_keys"] = names(s.input_keys);
    if (!s.output_keys.empty()) j["output_keys"] = names(s.output_keys);
    if (s.params) j["params"] = value(*s.params);
    if (!s.userdata.empty()) j["userdata"] = arguments(s.userdata);
    if (!s.callbacks.empty()) j["callbacks"] = arguments(s.callbacks);
    if (s.default_outcome) j["default_outcome"] = name(*s.default_outcome);
    addEdges(j, s);
    if (!s.args.empty()) j["args"] = arguments(s.args);
    if (!s.included_from.empty()) {
      Json list = Json::array();
      for (const Inclusion& inc : s.included_from) {
        list.push_back({{"file", sources_.path(inc.file)}, {"script", name(inc.script)}});
      }
      j["included_from"] = list;
    }
  }

  Json state(StateId id) const {
    const State& s = module_.state(id);
    Json j = {{"kind", stateKindName(s.kind)}, {"name", s.name.text}, {"loc", loc(s.loc)}};
    addFields(j, s);
    if (isContainer(s.kind)) {
      Json children = Json::array();
      for (StateId child : s.children) children.push_back(state(child));
      j["states"] = children;
    }
    return j;
  }

  const Module& module_;
  const SourceManager& sources_;
};

}  // namespace

std::string moduleToJson(const Module& module, const SourceManager& sources) {
  return JsonWriter(module, sources).run().dump(2) + "\n";
}

}  // namespace smachac::ir
