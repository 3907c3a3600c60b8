// UserDataStore (a locked map) and UserData (a state's checked, remapped view of a store).
#include "smachac/runtime/userdata.h"

#include <algorithm>
#include <mutex>

#include "smachac/runtime/state.h"
#include "text.h"

namespace smachac::runtime {

namespace {

/// "`a`, `b`" or "none".
std::string keyList(const Keys& keys) {
  if (keys.empty()) return "none";
  std::string out;
  for (const std::string& key : keys) out += (out.empty() ? "" : ", ") + backticked(key);
  return out;
}

}  // namespace

// --- UserDataStore ---------------------------------------------------------------------------

void UserDataStore::set(std::string_view key, Value value) { assign(key, std::move(value)); }

void UserDataStore::setText(std::string_view key, const char* text) { set(key, Value(text)); }

Value* UserDataStore::entryOf(std::string_view key) {
  std::lock_guard lock(mutex_);
  auto it = values_.find(key);
  return it == values_.end() ? nullptr : &it->second;
}

Value& UserDataStore::assign(std::string_view key, Value&& value) {
  std::lock_guard lock(mutex_);
  auto it = values_.find(key);
  if (it == values_.end()) return values_.emplace(std::string(key), std::move(value)).first->second;
  it->second = std::move(value);
  return it->second;
}

std::optional<Value> UserDataStore::find(std::string_view key) const {
  std::lock_guard lock(mutex_);
  auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

bool UserDataStore::contains(std::string_view key) const {
  std::lock_guard lock(mutex_);
  return values_.find(key) != values_.end();
}

std::vector<std::string> UserDataStore::keys() const {
  std::lock_guard lock(mutex_);
  std::vector<std::string> out;
  for (const auto& entry : values_) out.push_back(entry.first);
  return out;
}

Map UserDataStore::snapshot() const {
  std::lock_guard lock(mutex_);
  return values_;
}

Value UserDataStore::at(std::string_view key) const {
  std::optional<Value> value = find(key);
  if (!value) throw UserDataError("userdata key " + backticked(key) + " is not set");
  return std::move(*value);
}

std::string UserDataStore::typeMessage(std::string_view key, const TypeError& e) {
  return "userdata key " + backticked(key) + " holds " + e.actual() + ", not " + e.expected();
}

// --- UserData --------------------------------------------------------------------------------

UserData::UserData(UserDataStore& store, const State& state, const Remapping* remapping)
    : store_(&store), state_(&state), remapping_(remapping) {}

std::string_view UserData::remap(std::string_view key) const {
  if (remapping_ != nullptr) {
    auto it = remapping_->find(key);
    if (it != remapping_->end()) return it->second;
  }
  return key;
}

UserData::Slot& UserData::slotAt(std::vector<Slot>& slots, std::size_t count, std::size_t position,
                                 std::string_view key) const {
  if (slots.size() != count) slots.resize(count);  // the first use: a slot per declared key
  Slot& slot = slots[position];
  if (!slot.resolved) {
    slot.key = std::string(key);
    slot.target = std::string(remap(key));
    slot.resolved = true;
  }
  return slot;
}

UserData::Slot& UserData::inputSlot(std::string_view key, std::size_t position) const {
  const Keys& keys = state_->inputKeys();
  if (position >= keys.size() || keys[position] != key) {
    int found = indexIn(keys, key);
    if (found < 0) undeclared(key, false);
    position = static_cast<std::size_t>(found);
  }
  return slotAt(inputs_, keys.size(), position, key);
}

UserData::Slot& UserData::outputSlot(std::string_view key, std::size_t position) const {
  const Keys& keys = state_->outputKeys();
  if (position >= keys.size() || keys[position] != key) {
    int found = indexIn(keys, key);
    if (found < 0) undeclared(key, true);
    position = static_cast<std::size_t>(found);
  }
  return slotAt(outputs_, keys.size(), position, key);
}

void UserData::undeclared(std::string_view key, bool write) const {
  throw UserDataError("state " + backticked(state_->displayName()) +
                      (write ? " writes" : " reads") + " undeclared userdata key " +
                      backticked(key) + (write ? " (output keys: " : " (input keys: ") +
                      keyList(write ? state_->outputKeys() : state_->inputKeys()) + ")");
}

Value* UserData::entryOf(Slot& slot) const {
  if (slot.entry == nullptr) slot.entry = store_->entryOf(slot.target);
  return slot.entry;
}

std::optional<Value> UserData::findFirst(std::string_view key, std::size_t position) const {
  Value* entry = entryOf(inputSlot(key, position));
  if (entry == nullptr) return std::nullopt;
  return store_->load(*entry);
}

const Value& UserData::sharedCopy(std::size_t position) const {
  Slot& slot = inputs_[position];
  return read(slot, *slot.entry);
}

const Value& UserData::atOther(std::string_view key, std::size_t position) const {
  Slot& slot = inputSlot(key, position);
  if (const Value* entry = entryOf(slot)) return read(slot, *entry);
  std::string_view target = remap(key);
  std::string remapped = target == key ? "" : " (remapped to " + backticked(target) + ")";
  throw UserDataError("state " + backticked(state_->displayName()) + " reads userdata key " +
                      backticked(key) + remapped + ", which is not set");
}

const Value* UserData::findInputFirst(std::size_t position) const {
  const Keys& keys = state_->inputKeys();
  if (position >= keys.size()) undeclaredPosition(position, false);
  Slot& slot = slotAt(inputs_, keys.size(), position, keys[position]);
  const Value* entry = entryOf(slot);
  return entry != nullptr ? &read(slot, *entry) : nullptr;
}

void UserData::setOutputFirst(std::size_t position, Value&& value) {
  const Keys& keys = state_->outputKeys();
  if (position >= keys.size()) undeclaredPosition(position, true);
  setFirst(keys[position], position, std::move(value));
}

void UserData::setFirst(std::string_view key, std::size_t position, Value value) {
  Slot& slot = outputSlot(key, position);
  if (slot.entry == nullptr) {
    slot.entry = &store_->assign(slot.target, std::move(value));
  } else {
    store_->store(*slot.entry, std::move(value));
  }
  const std::string& target = slot.target;
  if (tracking_ && std::find(written_.begin(), written_.end(), target) == written_.end()) {
    written_.push_back(target);
  }
}

void UserData::undeclaredPosition(std::size_t position, bool write) const {
  throw UserDataError(
      "state " + backticked(state_->displayName()) + " has no " + (write ? "output" : "input") +
      " key at position " + std::to_string(position) + " (" + (write ? "output" : "input") +
      " keys: " + keyList(write ? state_->outputKeys() : state_->inputKeys()) + ")");
}

std::string UserData::typeMessage(std::string_view key, const TypeError& e) const {
  return "state " + backticked(state_->displayName()) + " reads userdata key " + backticked(key) +
         " as " + e.expected() + ", but it holds " + e.actual();
}

}  // namespace smachac::runtime
