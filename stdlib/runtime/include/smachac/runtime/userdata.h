// Userdata: the scope a container owns (UserDataStore) and the view a state executes with
// (UserData), which enforces the state's declared keys through its remapping, as SMACH's
// Remapper does:
//
//   the state reads `x`   -> `x` must be one of its input keys  -> the store's remapping[x] or x
//   the state writes `y`  -> `y` must be one of its output keys -> the store's remapping[y] or y
//
// Reads return copies (Values share their lists), so concurrent children of a Concurrence can
// use one scope safely: every store access takes the store's lock.
#pragma once

#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "smachac/runtime/errors.h"
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
  static std::string typeMessage(std::string_view key, const TypeError& e);

  mutable std::mutex mutex_;
  Map values_;
};

class State;

/// What a state's execute() receives: its own key names, checked against its declared keys.
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
  void checkInput(std::string_view key) const;
  std::string typeMessage(std::string_view key, const TypeError& e) const;

  UserDataStore* store_;
  const State* state_;
  const Remapping* remapping_;
  bool tracking_ = false;
  std::vector<std::string> written_;
};

}  // namespace smachac::runtime
