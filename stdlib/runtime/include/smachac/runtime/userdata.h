// Userdata: the scope a container owns (UserDataStore) and the view a state executes with
// (UserData), which enforces the state's declared keys through its remapping, as SMACH's
// Remapper does:
//
//   the state reads `x`   -> `x` must be one of its input keys  -> the store's remapping[x] or x
//   the state writes `y`  -> `y` must be one of its output keys -> the store's remapping[y] or y
//
// Reads return copies (Values share their lists), so concurrent children of a Concurrence can
// use one scope safely: every store access takes the store's lock.
//
// A view resolves each key once, at its first use: whether the state declares it, the store key
// it is remapped to, and the store's entry for it (a store never removes an entry, so the entry
// stays where it is). Every later access is a comparison with the few keys the state used and
// one locked copy, without a lookup in the remapping or the store.
#pragma once

#include <concepts>
#include <map>
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

/// A container's userdata scope. Thread-safe.
class UserDataStore {
 public:
  UserDataStore() = default;
  explicit UserDataStore(Map initial) : values_(std::move(initial)) {}
  UserDataStore(const UserDataStore&) = delete;
  UserDataStore& operator=(const UserDataStore&) = delete;

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
  /// find(key) and set(key, value) through `entry`, the view's cache of the key's entry:
  /// null until the key is set, then its entry (entries are never removed or moved).
  std::optional<Value> findAt(std::string_view key, Value*& entry);
  void setAt(std::string_view key, Value*& entry, Value&& value);

  mutable LightMutex mutex_;
  Map values_;  ///< never erased from: views keep pointers to its values
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
  Value at(std::string_view key) const;
  /// The value of an input key, or nothing when it is not set (still an error if undeclared).
  std::optional<Value> find(std::string_view key) const;
  /// Writes output key `key`; throws UserDataError when it is undeclared.
  void set(std::string_view key, Value value);

  const State& state() const { return *state_; }
  /// The store key `key` maps to.
  std::string_view remap(std::string_view key) const;

  /// Trace support: record the store keys written from now on.
  void trackWrites(bool on);
  const std::vector<std::string>& written() const { return written_; }

 private:
  /// A key the state used, resolved at its first use.
  struct Slot {
    std::string key;         ///< the state's name for it
    std::string target;      ///< the store's: remap(key)
    bool readable = false;   ///< checked: an input key
    bool writable = false;   ///< checked: an output key
    Value* entry = nullptr;  ///< the store's entry, once the key is set
  };

  Slot& slot(std::string_view key) const;
  void checkInput(std::string_view key) const;
  void checkOutput(std::string_view key) const;
  std::string typeMessage(std::string_view key, const TypeError& e) const;

  UserDataStore* store_;
  const State* state_;
  const Remapping* remapping_;
  bool tracking_ = false;
  std::vector<std::string> written_;
  mutable std::vector<Slot> slots_;  ///< the keys used so far, in the order of first use
};

}  // namespace smachac::runtime
