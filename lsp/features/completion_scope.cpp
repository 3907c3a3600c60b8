// The chain of states to the cursor, and what each declares.
#include "lsp/features/completion_scope.h"

#include <algorithm>
#include <unordered_map>

#include "frontend/shorthand.h"
#include "lsp/features/document_tree.h"

namespace smachac::lsp {
namespace {

std::vector<ScopeName> namesOf(const std::vector<ir::Name>& names) {
  std::vector<ScopeName> out;
  for (const ir::Name& name : names) out.push_back({name.text, name.loc});
  return out;
}

template <typename Entry>
std::vector<ScopeName> keysOf(const std::vector<Entry>& entries) {
  std::vector<ScopeName> out;
  for (const Entry& entry : entries) out.push_back({entry.key.text, entry.key.loc});
  return out;
}

/// The value of `key` (longhand or shorthand) in a state's mapping, or null.
const ir::Value* stateValue(const ir::Value* body, std::string_view key) {
  const ir::MapEntry* entry = body ? findKey(*body, key) : nullptr;
  return entry ? &entry->value : nullptr;
}

/// The states of a `states` list: one `NAME: body` mapping per item.
std::vector<const ir::MapEntry*> stateEntries(const ir::Value* states) {
  std::vector<const ir::MapEntry*> entries;
  if (!states || !states->isList()) return entries;
  for (const ir::Value& item : states->asList()) {
    if (!item.isMap()) continue;
    for (const ir::MapEntry& entry : item.asMap()) entries.push_back(&entry);
  }
  return entries;
}

const ir::Value* mappingOrNull(const ir::Value* value) {
  return value && value->isMap() ? value : nullptr;
}

std::string longhand(const std::string& key) {
  return std::string(frontend::longhandOf(key).value_or(key));
}

}  // namespace

void appendNew(std::vector<ScopeName>& names, const std::vector<ScopeName>& more) {
  for (const ScopeName& name : more) {
    if (!contains(names, name.text)) names.push_back(name);
  }
}

bool contains(const std::vector<ScopeName>& names, std::string_view text) {
  return std::any_of(names.begin(), names.end(),
                     [&](const ScopeName& name) { return name.text == text; });
}

std::optional<std::string> ScopeState::templateName() const {
  const ir::Value* written = stateValue(body_, "template");
  if (written && written->isString()) return written->asString();
  const ir::State* state = moduleState();
  if (state && state->template_name) return state->template_name->text;
  return std::nullopt;
}

bool ScopeState::isContainer() const {
  if (stateValue(body_, "states")) return true;
  const ir::State* state = moduleState();
  if (state && state->kind != ir::StateKind::Leaf) return true;
  std::optional<std::string> name = templateName();
  return name == "StateMachine" || name == "Concurrence";
}

std::vector<ScopeName> ScopeState::listed(std::string_view key) const {
  std::vector<ScopeName> names;
  const ir::Value* value = stateValue(body_, key);
  if (value && value->isString()) names.push_back({value->asString(), value->loc});
  if (value && value->isList()) {
    for (const ir::Value& item : value->asList()) {
      if (item.isString()) names.push_back({item.asString(), item.loc});
    }
  }
  appendNew(names, fromModule(key));
  return withoutCursor(std::move(names));
}

std::vector<ScopeName> ScopeState::mapKeys(std::string_view key) const {
  std::vector<ScopeName> names;
  const ir::Value* value = stateValue(body_, key);
  if (value && value->isMap()) {
    for (const ir::MapEntry& entry : value->asMap()) names.push_back({entry.key, entry.key_loc});
  }
  appendNew(names, fromModule(key));
  return withoutCursor(std::move(names));
}

std::vector<std::pair<std::string, std::string>> ScopeState::mapPairs(std::string_view key) const {
  std::vector<std::pair<std::string, std::string>> pairs;
  const ir::Value* value = stateValue(body_, key);
  if (value && value->isMap()) {
    for (const ir::MapEntry& entry : value->asMap()) {
      if (entry.value.isString()) pairs.emplace_back(entry.key, entry.value.asString());
    }
  }
  auto add = [&](const std::string& first, const std::string& second) {
    bool known =
        std::any_of(pairs.begin(), pairs.end(), [&](const auto& p) { return p.first == first; });
    if (!known) pairs.emplace_back(first, second);
  };
  const ir::State* state = moduleState();
  if (state && key == "transitions") {
    for (const ir::Transition& t : state->transitions) add(t.outcome.text, t.target.text);
  } else if (state && key == "remapping") {
    for (const ir::Remap& remap : state->remapping) add(remap.key.text, remap.parent_key.text);
  }
  return pairs;
}

std::vector<ScopeName> ScopeState::writtenKeys() const {
  std::vector<ScopeName> keys;
  if (body_ && body_->isMap()) {
    for (const ir::MapEntry& entry : body_->asMap()) {
      keys.push_back({longhand(entry.key), entry.key_loc});
    }
  }
  return withoutCursor(std::move(keys));
}

std::vector<ScopeState> ScopeState::children() const {
  std::unordered_map<std::string_view, ir::StateId> module_children;
  if (const ir::State* state = moduleState()) {
    for (ir::StateId id : state->children)
      module_children.emplace(module_->state(id).name.text, id);
  }
  std::vector<ScopeState> children;
  for (const ir::MapEntry* entry : stateEntries(stateValue(body_, "states"))) {
    auto found = module_children.find(entry->key);
    ir::StateId id = found == module_children.end() ? ir::StateId() : found->second;
    children.emplace_back(entry->key, mappingOrNull(&entry->value), module_, id, cursor_);
  }
  return children;
}

ScopeState ScopeState::child(const std::string& name, const ir::Value* body) const {
  ir::StateId id = id_.valid() ? module_->findChild(id_, name) : ir::StateId();
  return ScopeState(name, mappingOrNull(body), module_, id, cursor_);
}

std::optional<ScopeState> ScopeState::childAt(int64_t index, const std::string& name) const {
  const ir::Value* states = stateValue(body_, "states");
  if (!states || !states->isList() || static_cast<size_t>(index) >= states->asList().size()) {
    return std::nullopt;
  }
  const ir::Value& item = states->asList()[index];
  const ir::Value* body = item.isMap() ? item.find(name) : nullptr;
  if (!body) return std::nullopt;
  return child(name, body);
}

std::vector<ScopeName> ScopeState::fromModule(std::string_view key) const {
  const ir::State* state = moduleState();
  if (!state) return {};
  if (key == "outcomes") return namesOf(state->outcomes);
  if (key == "input_keys") return namesOf(state->input_keys);
  if (key == "output_keys") return namesOf(state->output_keys);
  if (key == "userdata") return keysOf(state->userdata);
  if (key == "callbacks") return keysOf(state->callbacks);
  if (key == "remapping") return keysOf(state->remapping);
  std::vector<ScopeName> names;
  if (key == "transitions") {
    for (const ir::Transition& t : state->transitions)
      names.push_back({t.outcome.text, t.outcome.loc});
  }
  return names;
}

std::vector<ScopeName> ScopeState::withoutCursor(std::vector<ScopeName> names) const {
  std::erase_if(names, [&](const ScopeName& name) { return cursor_.at(name.loc); });
  return names;
}

CursorScope locateCursor(const ir::Value& root, const ir::Module* module,
                         const std::vector<PathSegment>& path, CursorSpot cursor) {
  CursorScope scope;
  size_t pos = 0;
  ir::StateId root_id = module ? module->root() : ir::StateId();
  if (root.isList()) {
    bool names_state = path.size() >= 2 && path[0].isItem() && !path[1].isItem();
    if (!names_state || static_cast<size_t>(path[0].index) >= root.asList().size()) return scope;
    const std::string& name = path[1].key;
    const ir::Value* body = mappingOrNull(root.asList()[path[0].index].find(name));
    ir::StateId id = module ? module->findChild(root_id, name) : ir::StateId();
    scope.chain.emplace_back(name, body, module, id, cursor);
    scope.sub_script = true;
    pos = 2;
  } else {
    const ir::Value* name = stateValue(&root, "name");
    scope.chain.emplace_back(name && name->isString() ? name->asString() : "", mappingOrNull(&root),
                             module, root_id, cursor);
  }
  while (pos + 2 < path.size() && !path[pos].isItem() && longhand(path[pos].key) == "states" &&
         path[pos + 1].isItem() && !path[pos + 2].isItem()) {
    std::optional<ScopeState> child =
        scope.chain.back().childAt(path[pos + 1].index, path[pos + 2].key);
    if (!child) break;
    scope.chain.push_back(std::move(*child));
    pos += 3;
  }
  scope.rest.assign(path.begin() + static_cast<std::ptrdiff_t>(pos), path.end());
  if (!scope.rest.empty() && !scope.rest[0].isItem())
    scope.rest[0].key = longhand(scope.rest[0].key);
  return scope;
}

}  // namespace smachac::lsp
