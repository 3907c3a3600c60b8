// Renaming params in lookups.
#include "refactor/lookup_rewrite.h"

#include <functional>
#include <set>

#include "frontend/shorthand.h"
#include "refactor/flow_text.h"
#include "refactor/script_view.h"
#include "refactor/yaml_spans.h"

namespace smachac::refactor {
namespace {

/// The bodies of the states of a `states` list (nested lists flattened).
void forEachChild(const ir::Value& list, const std::function<void(const ir::Value&)>& visit) {
  if (!list.isList()) return;
  for (const ir::Value& item : list.asList()) {
    if (item.isList()) forEachChild(item, visit);
    if (item.isMap() && item.asMap().size() == 1 && item.asMap().front().value.isMap()) {
      visit(item.asMap().front().value);
    }
  }
}

bool ownsParam(const ir::Value& body, std::string_view key) {
  const ir::MapEntry* params = findKey(body, "params");
  return params && params->value.find(key) != nullptr;
}

/// The param-name scalar of `[params, x]` or `[[x]]`, and the list holding it.
std::optional<std::pair<const ir::Value*, const ir::Value*>> paramName(const ir::Value& list) {
  if (!list.isList()) return std::nullopt;
  const ir::List& items = list.asList();
  if (items.size() == 2 && items[0].isString() && items[0].asString() == "params" &&
      items[1].isString()) {
    return std::make_pair(&items[1], &list);
  }
  if (items.size() == 1 && items[0].isList() && items[0].asList().size() == 1 &&
      items[0].asList()[0].isString()) {
    return std::make_pair(&items[0].asList()[0], &items[0]);
  }
  return std::nullopt;
}

/// Visits the param lookups of a state and of the states it contains that inherit the keys.
class LookupWalker {
 public:
  using Visit =
      std::function<void(const std::string& key, const ir::Value& name, const ir::Value& holder)>;
  explicit LookupWalker(Visit visit) : visit_(std::move(visit)) {}

  void state(const ir::Value& body, const std::set<std::string, std::less<>>& keys) {
    for (const ir::MapEntry& entry : body.asMap()) {
      if (frontend::longhandOf(entry.key).value_or(entry.key) == "states") {
        forEachChild(entry.value, [&](const ir::Value& child) { nested(child, keys); });
      } else if (entry.value.isList()) {
        value(entry.value, keys);
      } else if (entry.value.isMap()) {
        for (const ir::MapEntry& inner : entry.value.asMap()) value(inner.value, keys);
      }
    }
  }

 private:
  void nested(const ir::Value& child, const std::set<std::string, std::less<>>& keys) {
    std::set<std::string, std::less<>> inherited;
    for (const std::string& key : keys) {
      if (!ownsParam(child, key)) inherited.insert(key);
    }
    if (!inherited.empty()) state(child, inherited);
  }

  void value(const ir::Value& list, const std::set<std::string, std::less<>>& keys) {
    if (!list.isList() || lookup(list, keys)) return;
    for (const ir::Value& part : list.asList()) lookup(part, keys);
  }

  bool lookup(const ir::Value& list, const std::set<std::string, std::less<>>& keys) {
    auto found = paramName(list);
    if (!found) return false;
    auto [name, holder] = *found;
    if (keys.contains(name->asString())) visit_(name->asString(), *name, *holder);
    return true;
  }

  Visit visit_;
};

}  // namespace

void renameParamLookups(const SourceText& text, EditList& edits, const ir::Value& body,
                        const Renames& renames) {
  if (renames.empty() || !body.isMap()) return;
  std::set<std::string, std::less<>> keys;
  for (const auto& [from, to] : renames) keys.insert(from);
  LookupWalker([&](const std::string& key, const ir::Value& name, const ir::Value& holder) {
    edits.replace(nodeSpan(text, name, itemContext(text, holder)), flowScalar(renames.at(key)));
  }).state(body, keys);
}

std::vector<std::string> usedParams(const ir::Value& body, const std::vector<std::string>& keys) {
  std::set<std::string, std::less<>> wanted(keys.begin(), keys.end());
  std::set<std::string, std::less<>> used;
  if (body.isMap()) {
    LookupWalker([&](const std::string& key, const ir::Value&, const ir::Value&) {
      used.insert(key);
    }).state(body, wanted);
  }
  std::vector<std::string> out;
  for (const std::string& key : keys) {
    if (used.contains(key) || subScriptInheriting(body, key)) out.push_back(key);
  }
  return out;
}

std::optional<std::string> subScriptInheriting(const ir::Value& body, std::string_view key) {
  const ir::MapEntry* states = findKey(body, "states");
  if (!states) {
    const ir::MapEntry* script = findKey(body, "script");
    if (script && script->value.isString()) return script->value.asString();
    return std::nullopt;
  }
  std::optional<std::string> found;
  forEachChild(states->value, [&](const ir::Value& child) {
    if (!found && !ownsParam(child, key)) found = subScriptInheriting(child, key);
  });
  return found;
}

}  // namespace smachac::refactor
