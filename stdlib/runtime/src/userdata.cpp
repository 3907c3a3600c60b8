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

void UserDataStore::set(std::string_view key, Value value) {
  std::lock_guard lock(mutex_);
  auto it = values_.find(key);
  if (it != values_.end()) {
    it->second = std::move(value);
  } else {
    values_.emplace(std::string(key), std::move(value));
  }
}

void UserDataStore::setText(std::string_view key, const char* text) { set(key, Value(text)); }

std::optional<Value> UserDataStore::findAt(std::string_view key, Value*& entry) {
  std::lock_guard lock(mutex_);
  if (entry == nullptr) {
    auto it = values_.find(key);
    if (it == values_.end()) return std::nullopt;
    entry = &it->second;
  }
  return *entry;
}

void UserDataStore::setAt(std::string_view key, Value*& entry, Value&& value) {
  std::lock_guard lock(mutex_);
  if (entry == nullptr) {
    auto it = values_.find(key);
    if (it == values_.end()) it = values_.emplace(std::string(key), Value()).first;
    entry = &it->second;
  }
  *entry = std::move(value);
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

UserData::Slot& UserData::slot(std::string_view key) const {
  for (Slot& slot : slots_) {
    if (slot.key == key) return slot;
  }
  return slots_.emplace_back(Slot{.key = std::string(key), .target = std::string(remap(key))});
}

void UserData::checkInput(std::string_view key) const {
  if (state_->declaresInput(key)) return;
  throw UserDataError("state " + backticked(state_->displayName()) +
                      " reads undeclared userdata key " + backticked(key) +
                      " (input keys: " + keyList(state_->inputKeys()) + ")");
}

void UserData::checkOutput(std::string_view key) const {
  if (state_->declaresOutput(key)) return;
  throw UserDataError("state " + backticked(state_->displayName()) +
                      " writes undeclared userdata key " + backticked(key) +
                      " (output keys: " + keyList(state_->outputKeys()) + ")");
}

std::optional<Value> UserData::find(std::string_view key) const {
  Slot& resolved = slot(key);
  if (!resolved.readable) {
    checkInput(key);
    resolved.readable = true;
  }
  return store_->findAt(resolved.target, resolved.entry);
}

Value UserData::at(std::string_view key) const {
  std::optional<Value> value = find(key);
  if (value) return std::move(*value);
  std::string_view target = remap(key);
  std::string remapped = target == key ? "" : " (remapped to " + backticked(target) + ")";
  throw UserDataError("state " + backticked(state_->displayName()) + " reads userdata key " +
                      backticked(key) + remapped + ", which is not set");
}

void UserData::set(std::string_view key, Value value) {
  Slot& resolved = slot(key);
  if (!resolved.writable) {
    checkOutput(key);
    resolved.writable = true;
  }
  store_->setAt(resolved.target, resolved.entry, std::move(value));
  const std::string& target = resolved.target;
  if (tracking_ && std::find(written_.begin(), written_.end(), target) == written_.end()) {
    written_.push_back(target);
  }
}

void UserData::trackWrites(bool on) {
  tracking_ = on;
  written_.clear();
}

std::string UserData::typeMessage(std::string_view key, const TypeError& e) const {
  return "state " + backticked(state_->displayName()) + " reads userdata key " + backticked(key) +
         " as " + e.expected() + ", but it holds " + e.actual();
}

}  // namespace smachac::runtime
