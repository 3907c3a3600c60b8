// Conversion of IR values into template values.
#include "backends/generator/template_values.h"

#include <cstdint>
#include <string>

namespace smachac::generator {

std::string backtickForm(std::string_view code) {
  std::string out;
  out.reserve(code.size() + 2);
  out += '`';
  out += code;
  out += '`';
  return out;
}

tmpl::Value ValueConverter::convert(const ir::Value& value) {
  if (value.behavior_param != 0 && !param_refs_.empty()) {
    auto ref = param_refs_.find(value.behavior_param);
    if (ref != param_refs_.end()) return tmpl::Value::string(backtickForm("self." + ref->second));
  }
  switch (value.kind()) {
    case ir::ValueKind::Null:
      return tmpl::Value::none();
    case ir::ValueKind::Bool:
      return tmpl::Value::boolean(value.asBool());
    case ir::ValueKind::Int:
      return tmpl::Value::integer(value.asInt());
    case ir::ValueKind::Float:
      return tmpl::Value::real(value.asFloat());
    case ir::ValueKind::String: {
      tmpl::Value s = tmpl::Value::string(value.asString());
      if (value.forced_string) {
        forced_ids_.insert(s.identity());
        forced_.push_back(s);
      }
      return s;
    }
    case ir::ValueKind::Expression:
      return tmpl::Value::string(backtickForm(value.asExpression().code));
    case ir::ValueKind::List: {
      std::vector<tmpl::Value> items;
      items.reserve(value.asList().size());
      for (const ir::Value& item : value.asList()) items.push_back(convert(item));
      return tmpl::Value::newList(std::move(items));
    }
    case ir::ValueKind::Map: {
      tmpl::Value dict = tmpl::Value::newDict();
      for (const ir::MapEntry& entry : value.asMap()) {
        dict.dict().setString(entry.key, convert(entry.value));
      }
      return dict;
    }
  }
  return tmpl::Value::none();
}

tmpl::Value ValueConverter::names(const std::vector<ir::Name>& names) {
  std::vector<tmpl::Value> items;
  items.reserve(names.size());
  for (const ir::Name& name : names) items.push_back(text(name.text));
  return tmpl::Value::newList(std::move(items));
}

tmpl::Value ValueConverter::cachedText(const void* identity, std::string_view text) {
  CachedText& slot = texts_[(reinterpret_cast<uintptr_t>(identity) >> 4) % kTextCacheSize];
  if (slot.key != identity) {
    slot.key = identity;
    slot.value = tmpl::Value::string(std::string(text));
  }
  return slot.value;
}

void ValueConverter::referToBehaviorParams(std::unordered_map<uint32_t, std::string> refs) {
  param_refs_ = std::move(refs);
}

bool ValueConverter::isForcedString(const tmpl::Value& value) const {
  return value.isString() && forced_ids_.count(value.identity()) > 0;
}

}  // namespace smachac::generator
