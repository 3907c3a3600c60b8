// An optional value kept on the heap: 8 bytes in its holder where std::optional<T> holds the
// whole T. For the fields a state rarely sets (`params`, `default_outcome`): a big script has
// a state every few lines, and an unset field should cost it little.
//
// Rules: copies are deep (a Boxed behaves as a value, like std::optional); reads go through
// `*`, `->` and the test for presence, as with std::optional.
#pragma once

#include <memory>
#include <optional>
#include <utility>

namespace smachac::ir {

template <class T>
class Boxed {
 public:
  Boxed() = default;
  Boxed(std::nullopt_t) {}
  Boxed(T value) : value_(std::make_unique<T>(std::move(value))) {}
  Boxed(const Boxed& other) : value_(other ? std::make_unique<T>(*other) : nullptr) {}
  Boxed(Boxed&&) noexcept = default;
  Boxed& operator=(const Boxed& other) {
    if (this != &other) value_ = other ? std::make_unique<T>(*other) : nullptr;
    return *this;
  }
  Boxed& operator=(Boxed&&) noexcept = default;
  ~Boxed() = default;

  explicit operator bool() const { return value_ != nullptr; }
  T& operator*() { return *value_; }
  const T& operator*() const { return *value_; }
  T* operator->() { return value_.get(); }
  const T* operator->() const { return value_.get(); }
  /// A copy as a std::optional, for code that takes one.
  std::optional<T> copy() const { return value_ ? std::optional<T>(*value_) : std::nullopt; }

 private:
  std::unique_ptr<T> value_;
};

}  // namespace smachac::ir
