// Userdata: the scope a container owns (UserDataStore) and the view a state executes with
// (UserData), which enforces the state's declared keys through its remapping, as SMACH's
// Remapper does:
//
//   the state reads `x`   -> `x` must be one of its input keys  -> the store's remapping[x] or x
//   the state writes `y`  -> `y` must be one of its output keys -> the store's remapping[y] or y
//
// Reads return copies (Values share their lists), so concurrent children of a Concurrence can
// use one scope safely: a shared store (a Concurrence's) is locked at every access. A state
// machine's store is used by one thread at a time (its children run one after another), so
// views read and write it without the lock; from outside, use it only while nothing runs.
//
// A view keeps a slot per declared key (its position in inputKeys() or outputKeys()),
// resolved at the key's first use: the store key it is remapped to and the store's entry for
// it (a store never removes an entry, so the entry stays where it is). Generated code names
// the position with the key (`ud.at("n", 0)`), so an access is one comparison of the key with
// the declared one and a copy, without a search, a lookup in the remapping or the store.
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
  /// A copy of / an assignment to an entry, under the lock when the store is shared.
  Value load(const Value& entry) const {
    if (!shared_) return entry;
    std::lock_guard lock(mutex_);
    return entry;
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
  Value at(std::string_view key, std::size_t position) const {
    if (const Value* entry = known(inputs_, key, position)) return store_->load(*entry);
    return atFirst(key, position);
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
  };

  /// The entry of the declared key `key` at `position` once resolved and set; else null.
  static Value* known(const std::vector<Slot>& slots, std::string_view key, std::size_t position) {
    if (position >= slots.size()) return nullptr;
    const Slot& slot = slots[position];
    return slot.entry != nullptr && slot.key == key ? slot.entry : nullptr;
  }
  /// at(), find() and set() when known() does not know the key: a search, a check, a lookup.
  Value atFirst(std::string_view key, std::size_t position) const;
  std::optional<Value> findFirst(std::string_view key, std::size_t position) const;
  void setFirst(std::string_view key, std::size_t position, Value value);
  Slot& inputSlot(std::string_view key, std::size_t position) const;
  Slot& outputSlot(std::string_view key, std::size_t position) const;
  Slot& slotAt(std::vector<Slot>& slots, std::size_t count, std::size_t position,
               std::string_view key) const;
  [[noreturn]] void undeclared(std::string_view key, bool write) const;
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
