// Building a container's userdata scope: interning keys, collecting literal definitions, the
// reads and writes of every child (through its remapping) and the container's own interface.
#include "passes/analysis/userdata_scope.h"

#include <algorithm>

#include "passes/analysis/outcomes.h"

namespace smachac::passes {
namespace {

/// Keys a container defines for itself: its own userdata and its leaves'.
NameSet ownDefaults(const ir::Module& module, const ir::State& container) {
  NameSet keys;
  for (const ir::Argument& entry : container.userdata) keys.insert(entry.key.text);
  for (ir::StateId id : container.children) {
    const ir::State& child = module.state(id);
    if (ir::isContainer(child.kind)) continue;
    for (const ir::Argument& entry : child.userdata) keys.insert(entry.key.text);
  }
  return keys;
}

}  // namespace

const ir::Name& remappedName(const ir::State& state, const ir::Name& key) {
  for (const ir::Remap& remap : state.remapping) {
    if (remap.key.text == key.text) return remap.parent_key;
  }
  return key;
}

UserdataScope::UserdataScope(const ir::Module& module, ir::StateId container)
    : container_(container) {
  const ir::State& c = module.state(container);
  addLiterals(c.userdata, kContainer);
  for (uint32_t i = 0; i < c.children.size(); ++i) {
    const ir::State& child = module.state(c.children[i]);
    if (!ir::isContainer(child.kind)) addLiterals(child.userdata, i);
  }
  for (const ir::Name& key : c.input_keys) {
    inputs_.push_back({intern(key.text), &key, &key, false});
    initial_[inputs_.back().key] = 1;
  }
  for (const ir::Name& key : c.output_keys) exit_reads_.push_back({intern(key.text), &key, &key});
  for (ir::StateId child : c.children) addChild(module, child);
}

uint32_t UserdataScope::intern(std::string_view name) {
  auto [it, inserted] = index_.try_emplace(name, static_cast<uint32_t>(names_.size()));
  if (inserted) {
    names_.push_back(name);
    initial_.push_back(0);
    first_writer_.push_back(kNone);
  }
  return it->second;
}

KeyUse UserdataScope::use(const ir::State& state, const ir::Name& key) {
  const ir::Name& scope_name = remappedName(state, key);
  return {intern(scope_name.text), &key, &scope_name, false};
}

void UserdataScope::addLiterals(const std::vector<ir::Argument>& userdata, uint32_t child) {
  for (const ir::Argument& entry : userdata) {
    literals_.push_back({intern(entry.key.text), &entry, child});
    initial_[literals_.back().key] = 1;
  }
}

void UserdataScope::addChild(const ir::Module& module, ir::StateId child) {
  const ir::State& s = module.state(child);
  NameSet defaults;
  if (ir::isContainer(s.kind) && !s.input_keys.empty()) defaults = ownDefaults(module, s);
  for (const ir::Name& key : s.input_keys) {
    reads_.push_back(use(s, key));
    reads_.back().optional = defaults.contains(key.text);
  }
  read_begin_.push_back(static_cast<uint32_t>(reads_.size()));
  for (const ir::Name& key : s.output_keys) {
    writes_.push_back(use(s, key));
    uint32_t& first = first_writer_[writes_.back().key];
    if (first == kNone) first = static_cast<uint32_t>(writes_.size() - 1);
  }
  write_begin_.push_back(static_cast<uint32_t>(writes_.size()));
}

std::vector<std::string> UserdataScope::keyNames() const { return {names_.begin(), names_.end()}; }

std::optional<uint32_t> UserdataScope::find(std::string_view name) const {
  auto it = index_.find(name);
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

std::span<const KeyUse> UserdataScope::reads(uint32_t child) const {
  return {reads_.data() + read_begin_[child], reads_.data() + read_begin_[child + 1]};
}

std::span<const KeyUse> UserdataScope::writes(uint32_t child) const {
  return {writes_.data() + write_begin_[child], writes_.data() + write_begin_[child + 1]};
}

std::optional<std::pair<uint32_t, const KeyUse*>> UserdataScope::firstWriter(uint32_t key) const {
  uint32_t index = first_writer_[key];
  if (index == kNone) return std::nullopt;
  auto it = std::upper_bound(write_begin_.begin(), write_begin_.end(), index);
  uint32_t child = static_cast<uint32_t>(it - write_begin_.begin()) - 1;
  return std::make_pair(child, &writes_[index]);
}

const UserdataScope& UserdataScopeCache::get(const ir::Module& module, ir::StateId container) {
  if (module_ != &module || state_count_ != module.stateCount()) {
    clear();
    module_ = &module;
    state_count_ = module.stateCount();
  }
  std::unique_ptr<UserdataScope>& scope = scopes_[container.index];
  if (!scope) scope = std::make_unique<UserdataScope>(module, container);
  return *scope;
}

void UserdataScopeCache::clear() {
  module_ = nullptr;
  state_count_ = 0;
  scopes_.clear();
}

const UserdataScope& userdataScope(PassContext& context, const ir::Module& module,
                                   ir::StateId container) {
  if (!context.userdata_scopes) context.userdata_scopes = std::make_shared<UserdataScopeCache>();
  return context.userdata_scopes->get(module, container);
}

}  // namespace smachac::passes
