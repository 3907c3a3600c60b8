// CallbacksLiteral: the literal form of Callbacks, as generated code writes a state's
// callbacks:
//
//   rt::CallbacksLiteral{{"speed", [](rt::UserData& ud) { return ud.get<double>("speed"); }}}
//
// Its entries are trivially destructible (a key view and pointers), so a statement that gives
// a state its callbacks destroys nothing, and a lambda without captures costs one small
// function template (invokeEmpty, which makes the closure and calls it) instead of
// Callback's constructor and a KeyedCallback with its vector. It converts to Callbacks, which
// the library builds out of line. The callables it points at must live through the statement
// (temporaries do).
#pragma once

#include <initializer_list>
#include <string_view>
#include <type_traits>
#include <vector>

#include "smachac/runtime/callback.h"
#include "smachac/runtime/literals.h"
#include "smachac/runtime/value.h"

namespace smachac::runtime {

struct KeyedCallback;

/// One entry: an output key and its callback, kept as pointers.
class CallbackLiteral {
 public:
  template <detail::CallbackSource F>
  CallbackLiteral(const char* key, const F& callable) : key_(key) {
    if constexpr (std::is_function_v<F>) {
      function_ = reinterpret_cast<void (*)()>(&callable);
      make_ = &makeFromFunction<F>;
    } else if constexpr (std::is_empty_v<F> && std::is_trivially_default_constructible_v<F> &&
                         std::is_trivially_copyable_v<F>) {
      // A lambda without captures: any object of its type is the same callable.
      invoke_ = &invokeEmpty<F>;
    } else {
      object_ = &callable;
      make_ = &makeFromObject<F>;
    }
  }

  /// The key (a null key reads as "").
  std::string_view key() const { return cStringText(key_); }
  /// The owning form (a copy of the callable).
  Callback callback() const;

 private:
  template <class F>
  static Value invokeEmpty(UserData& userdata) {
    return F{}(userdata);
  }
  template <class F>
  static Callback makeFromFunction(const CallbackLiteral& entry) {
    return Callback(reinterpret_cast<F*>(entry.function_));
  }
  template <class F>
  static Callback makeFromObject(const CallbackLiteral& entry) {
    return Callback(*static_cast<const F*>(entry.object_));
  }

  const char* key_;                                     ///< a C string: nothing to make at the call
  Value (*invoke_)(UserData&) = nullptr;                ///< a lambda without captures
  void (*function_)() = nullptr;                        ///< a function, as void (*)()
  const void* object_ = nullptr;                        ///< any other callable
  Callback (*make_)(const CallbackLiteral&) = nullptr;  ///< copies function_ or object_
};

/// Callbacks' literal form, in the order they run; converts to Callbacks.
class CallbacksLiteral {
 public:
  CallbacksLiteral() = default;
  CallbacksLiteral(std::initializer_list<CallbackLiteral> entries) : entries_(entries) {}

  /// Implicit, so that a state class taking Callbacks can be given a CallbacksLiteral.
  operator std::vector<KeyedCallback>() const;

 private:
  std::initializer_list<CallbackLiteral> entries_;
};

}  // namespace smachac::runtime
