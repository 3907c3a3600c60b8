// Userdata: the scope a container owns (UserDataStore) and the view a state executes with
// (UserData), which enforces the state's declared keys through its remapping, as SMACH's
// Remapper does:
//
//   the state reads `x`   -> `x` must be one of its input keys  -> the store's remapping[x] or x
//   the state writes `y`  -> `y` must be one of its output keys -> the store's remapping[y] or y
//
// Reads from a shared store (a Concurrence's, whose children run at the same time) are copies
// made under its lock (Values share their lists). A state machine's store is used by one
// thread at a time (its children run one after another), so views read and write it without
// the lock, and a read by position gives the entry itself; from outside, use such a store only
// while nothing runs.
//
// A view keeps a slot per declared key (its position in inputKeys() or outputKeys()),
// resolved at the key's first use: the store key it is remapped to and the store's entry for
// it (a store never removes an entry, so the entry stays where it is). Generated code names
// the position with the key (`ud.at("n", 0)`), so an access is one comparison of the key with
// the declared one, without a search, a lookup in the remapping or the store. The core states
// know their keys' positions and read and write by position alone (findInput, setOutput).
#pragma once

#include <concepts>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "smachac/runtime/errors.h"
#include "smachac/runtime/light_mutex.h"
#include "smachac/runtime/literals.h"
#include "smachac/runtime/value.h"

namespace smachac::runtime {

using Keys = std::vector<std::string>;

namespace detail {
/// value.as<T>(), a TypeError turned into a UserDataError with message(error).
template <class T, class Message>
T convert(const Value& value, Message message) {
  try {
    return value.as<T>();
  } catch (const TypeError& e) {
    throw UserDataError(message(e));
  }
}
}  // namespace detail

/// State key -> key in the parent container's userdata.
using Remapping = std::map<std::string, std::string, std::less<>>;

/// A container's userdata scope. Thread-safe, except views of a store that is not shared.
class UserDataStore {
 public:
  UserDataStore() = default;
  explicit UserDataStore(Map initial) : values_(std::move(initial)) {}
  UserDataStore(const UserDataStore&) = delete;
  UserDataStore& operator=(const UserDataStore&) = delete;

  /// Whether states of several threads use the store at the same time (the default, and a
  /// Concurrence's scope). A state machine makes its scope unshared: its views skip the lock.
  void setShared(bool shared) { shared_ = shared; }

  void set(std::string_view key, Value value);
  /// set(key, Value(text)) without a Value to destroy at the call: generated code sets its
  /// string userdata with it. A template, so that `0` and `nullptr` still make Values.
  template <std::same_as<char> Char>
  void set(std::string_view key, const Char* text) {
    setText(key, text);
  }
  /// The same with a C-string key, as generated code writes both: no std::string_view to make
  /// at the call (about a tenth of a millisecond of compile time per line at -O0).
  template <std::same_as<char> Char>
  void set(const Char* key, const Char* text) {
    setText(cStringText(key), text);
  }
  std::optional<Value> find(std::string_view key) const;
  bool contains(std::string_view key) const;
  /// Sorted.
  std::vector<std::string> keys() const;
  /// A copy of every entry.
  Map snapshot() const;

  /// Throws UserDataError: "userdata key `x` is not set", "userdata key `x` holds a string, not
  /// a double".
  template <class T>
  T get(std::string_view key) const {
    return detail::convert<T>(at(key), [&](const TypeError& e) { return typeMessage(key, e); });
  }
  Value at(std::string_view key) const;

 private:
  friend class UserData;

  static std::string typeMessage(std::string_view key, const TypeError& e);
  void setText(std::string_view key, const char* text);
  /// The entry of `key`, or null when it is not set (entries are never removed or moved).
  Value* entryOf(std::string_view key);
  /// set(key, value), returning the entry.
  Value& assign(std::string_view key, Value&& value);
  /// A copy of / an assignment to an entry, under the lock when the store is shared;
  /// copy() always locks.
  Value load(const Value& entry) const {
    if (!shared_) return entry;
    std::lock_guard lock(mutex_);
    return entry;
  }
  void copy(const Value& entry, Value& out) const {
    std::lock_guard lock(mutex_);
    out = entry;
  }
  void store(Value& entry, Value&& value) {
    if (!shared_) {
      entry = std::move(value);
      return;
    }
    std::lock_guard lock(mutex_);
    entry = std::move(value);
  }

  mutable LightMutex mutex_;
  Map values_;  ///< never erased from: views keep pointers to its values
  bool shared_ = true;
};

class State;

/// What a state's execute() receives: its own key names, checked against its declared keys.
/// Used by one thread at a time (its state's execution): it keeps the keys it resolved.
class UserData {
 public:
  /// A view over `store` for `state`. `remapping` must outlive the view; nullptr: none.
  UserData(UserDataStore& store, const State& state, const Remapping* remapping = nullptr);

  /// Reads input key `key`. Throws UserDataError when the key is undeclared, not set, or of
  /// another type: "state `SM/FOO` reads userdata key `x` as a double, but it holds a string".
  template <class T>
  T get(std::string_view key) const {
    return detail::convert<T>(at(key), [&](const TypeError& e) { return typeMessage(key, e); });
  }
  Value at(std::string_view key) const { return at(key, kUnknownPosition); }
  /// The value of an input key, or nothing when it is not set (still an error if undeclared).
  std::optional<Value> find(std::string_view key) const { return find(key, kUnknownPosition); }
  /// Writes output key `key`; throws UserDataError when it is undeclared.
  void set(std::string_view key, Value value) { set(key, kUnknownPosition, std::move(value)); }

  /// The same for a key at `position` in inputKeys() (at, find) or outputKeys() (set): what
  /// generated code and the core states call. When the key is not there, it is searched for.
  /// at() returns the entry itself when the store is not shared (valid until the key is
  /// written), else a copy the view keeps for the key (valid until the view reads it again).
  const Value& at(std::string_view key, std::size_t position) const {
    // The rest out of line, so that this inlines where it is called.
    const Value* entry = known(inputs_, key, position);
    if (entry == nullptr) return atOther(key, position);
    return store_->shared_ ? sharedCopy(position) : *entry;
  }
  std::optional<Value> find(std::string_view key, std::size_t position) const {
    if (const Value* entry = known(inputs_, key, position)) return store_->load(*entry);
    return findFirst(key, position);
  }
  void set(std::string_view key, std::size_t position, Value value) {
    Value* entry = known(outputs_, key, position);
    if (entry == nullptr || tracking_) return setFirst(key, position, std::move(value));
    store_->store(*entry, std::move(value));
  }

  /// The input key at `position` in inputKeys(), or null when it is not set: what a state
  /// that knows its keys' positions reads (as at(), a copy the view keeps when shared).
  /// Throws UserDataError when there is no input key at `position`.
  const Value* findInput(std::size_t position) const {
    if (position < inputs_.size()) {
      Slot& slot = inputs_[position];
      if (slot.entry != nullptr) return &read(slot, *slot.entry);
    }
    return findInputFirst(position);
  }
  /// Writes the output key at `position` in outputKeys().
  void setOutput(std::size_t position, Value&& value) {
    if (position < outputs_.size()) {
      Slot& slot = outputs_[position];
      if (slot.entry != nullptr && !tracking_) return store_->store(*slot.entry, std::move(value));
    }
    setOutputFirst(position, std::move(value));
  }
  /// The same with a value the caller keeps: an entry that already holds it is not written.
  void setOutput(std::size_t position, const Value& value) {
    if (position < outputs_.size() && !store_->shared_) {
      Slot& slot = outputs_[position];
      if (slot.entry != nullptr && !tracking_) {
        if (!slot.entry->identical(value)) *slot.entry = value;
        return;
      }
    }
    setOutputFirst(position, Value(value));
  }

  const State& state() const { return *state_; }
  /// The store key `key` maps to.
  std::string_view remap(std::string_view key) const;

  /// Trace support: record the store keys written from now on.
  void trackWrites(bool on) {
    tracking_ = on;
    written_.clear();
  }
  const std::vector<std::string>& written() const { return written_; }

 private:
  static constexpr std::size_t kUnknownPosition = ~std::size_t{0};

  /// A declared key, resolved at its first use.
  struct Slot {
    std::string key;         ///< the state's name for it
    std::string target;      ///< the store's: remap(key)
    Value* entry = nullptr;  ///< the store's entry, once the key is set
    bool resolved = false;   ///< key and target are set
    Value copy;              ///< the last value read from a shared store
  };

  /// The entry of the declared key `key` at `position` once resolved and set; else null.
  static Value* known(const std::vector<Slot>& slots, std::string_view key, std::size_t position) {
    if (position >= slots.size()) return nullptr;
    const Slot& slot = slots[position];
    // Sized by `key`, which generated code writes as a literal: no call to memcmp.
    bool same = slot.key.size() == key.size() &&
                std::char_traits<char>::compare(slot.key.data(), key.data(), key.size()) == 0;
    return slot.entry != nullptr && same ? slot.entry : nullptr;
  }
  /// What a read by position gives: `entry` itself, or from a shared store the slot's copy.
  const Value& read(Slot& slot, const Value& entry) const {
    if (!store_->shared_) return entry;
    store_->copy(entry, slot.copy);
    return slot.copy;
  }
  /// at() of a key known() does not know: a search, a check, a lookup.
  const Value& atOther(std::string_view key, std::size_t position) const;
  /// read() of the known input slot at `position`, from a shared store.
  const Value& sharedCopy(std::size_t position) const;
  /// find() and set() when known() does not know the key: a search, a check, a lookup.
  std::optional<Value> findFirst(std::string_view key, std::size_t position) const;
  void setFirst(std::string_view key, std::size_t position, Value value);
  const Value* findInputFirst(std::size_t position) const;
  void setOutputFirst(std::size_t position, Value&& value);
  /// The entry of a resolved input slot, found in the store when not yet known; or null.
  Value* entryOf(Slot& slot) const;
  Slot& inputSlot(std::string_view key, std::size_t position) const;
  Slot& outputSlot(std::string_view key, std::size_t position) const;
  Slot& slotAt(std::vector<Slot>& slots, std::size_t count, std::size_t position,
               std::string_view key) const;
  [[noreturn]] void undeclared(std::string_view key, bool write) const;
  [[noreturn]] void undeclaredPosition(std::size_t position, bool write) const;
  std::string typeMessage(std::string_view key, const TypeError& e) const;

  UserDataStore* store_;
  const State* state_;
  const Remapping* remapping_;
  bool tracking_ = false;
  std::vector<std::string> written_;
  mutable std::vector<Slot> inputs_;   ///< per input key, by position
  mutable std::vector<Slot> outputs_;  ///< per output key, by position
};

}  // namespace smachac::runtime
