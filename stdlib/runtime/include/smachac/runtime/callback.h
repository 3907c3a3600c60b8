// Callback: what a core state calls to compute the value of one output key from the userdata,
// any callable taking UserData& and returning something Value converts from.
//
// A lambda without captures or a function is kept as a plain function pointer, called through
// a converter shared by every callable with the same result type, or directly when it returns
// a Value (as generated code's do); only other callables (a lambda with captures, a function
// object) are kept in a std::function. So a program with hundreds of lambda callbacks
// instantiates a few small templates per lambda, not the dozen of a std::function each: it
// compiles seconds faster, and a call costs no more.
#pragma once

#include <concepts>
#include <functional>
#include <type_traits>
#include <utility>

#include "smachac/runtime/value.h"

namespace smachac::runtime {

class UserData;
class Callback;

namespace detail {
/// What Callback's constructor takes: a callable with a UserData& that is not a Callback.
template <class F>
concept CallbackSource =
    !std::same_as<std::remove_cvref_t<F>, Callback> && requires(F & callable, UserData& userdata) {
  callable(userdata);
};
}  // namespace detail

class Callback {
 public:
  Callback() = default;

  template <detail::CallbackSource F>
  Callback(F callable) {
    using Result = decltype(callable(std::declval<UserData&>()));
    if constexpr (std::same_as<Result, Value> &&
                  requires { static_cast<Value (*)(UserData&)>(callable); }) {
      value_function_ = static_cast<Value (*)(UserData&)>(callable);
    } else if constexpr (requires { static_cast<Result (*)(UserData&)>(callable); }) {
      function_ = reinterpret_cast<void (*)()>(static_cast<Result (*)(UserData&)>(callable));
      call_ = &callFunction<Result>;
    } else {
      object_ = std::move(callable);
    }
  }

  /// Calls the callable; throws std::bad_function_call when there is none.
  Value operator()(UserData& userdata) const {
    if (value_function_ != nullptr) return value_function_(userdata);
    return call_ != nullptr ? call_(function_, userdata) : object_(userdata);
  }
  explicit operator bool() const {
    return value_function_ != nullptr || call_ != nullptr || static_cast<bool>(object_);
  }

 private:
  template <class Result>
  static Value callFunction(void (*function)(), UserData& userdata) {
    return reinterpret_cast<Result (*)(UserData&)>(function)(userdata);
  }

  Value (*value_function_)(UserData&) = nullptr;    ///< a function returning a Value, or none
  Value (*call_)(void (*)(), UserData&) = nullptr;  ///< callFunction<Result>, or none
  void (*function_)() = nullptr;                    ///< the function, as Result (*)(UserData&)
  std::function<Value(UserData&)> object_;          ///< any other callable
};

}  // namespace smachac::runtime
