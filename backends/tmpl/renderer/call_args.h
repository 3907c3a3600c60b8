// Arguments of a call (positional and keyword), and ArgBinder, which binds them to a Python-like
// parameter list for built-in filters, tests, methods and globals.
#pragma once

#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/tmpl/values/value.h"

namespace smachac::tmpl {

struct CallArgs {
  std::span<const Value> positional;
  std::span<const std::pair<const std::string*, Value>> keyword;

  size_t size() const { return positional.size() + keyword.size(); }
  const Value* findKeyword(std::string_view name) const;
};

/// A vector that keeps its first N elements inline (no allocation for short argument lists).
/// (clang-tidy 14 reports `__i0`, the loop variable of an implicit array initialisation it
/// makes up for `inline_`, as a name in the wrong style.)
template <class T, size_t N>
class SmallVector {  // NOLINT(readability-identifier-naming)
 public:
  template <class... Args>
  void emplaceBack(Args&&... args) {
    if (heap_.empty() && size_ < N) {
      inline_[size_++] = T(std::forward<Args>(args)...);
      return;
    }
    if (heap_.empty()) {
      heap_.reserve(N * 2);
      for (size_t i = 0; i < size_; ++i) heap_.push_back(std::move(inline_[i]));
    }
    heap_.emplace_back(std::forward<Args>(args)...);
  }
  void pushBack(T value) { emplaceBack(std::move(value)); }
  void reserve(size_t) {}
  const T* data() const { return heap_.empty() ? inline_ : heap_.data(); }
  T* data() { return heap_.empty() ? inline_ : heap_.data(); }
  size_t size() const { return heap_.empty() ? size_ : heap_.size(); }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size(); }
  T* begin() { return data(); }
  T* end() { return data() + size(); }
  T& operator[](size_t i) { return data()[i]; }
  const T& operator[](size_t i) const { return data()[i]; }
  operator std::span<const T>() const { return {data(), size()}; }  // NOLINT

 private:
  T inline_[N];
  size_t size_ = 0;
  std::vector<T> heap_;
};

/// Owning storage for CallArgs built at run time.
struct OwnedArgs {
  SmallVector<Value, 4> positional;
  SmallVector<std::pair<const std::string*, Value>, 3> keyword;
  CallArgs view() const { return CallArgs{positional, keyword}; }
};

/// Binds CallArgs to named parameters: `ArgBinder b(args, "indent", {"width", "first"});`.
/// Raises Fault for too many arguments, unknown keywords or duplicates.
class ArgBinder {
 public:
  ArgBinder(const CallArgs& args, std::string_view function,
            std::initializer_list<std::string_view> params);
  /// The argument for parameter `index`, or null when not given.
  const Value* get(size_t index) const { return bound_[index]; }
  Value get(size_t index, Value fallback) const {
    return bound_[index] ? *bound_[index] : std::move(fallback);
  }
  bool has(size_t index) const { return bound_[index] != nullptr; }
  /// Raises Fault unless parameter `index` was given.
  const Value& require(size_t index) const;
  int64_t getInt(size_t index, int64_t fallback) const;
  bool getBool(size_t index, bool fallback) const;

 private:
  static constexpr size_t kMaxParams = 8;
  std::string_view function_;
  std::string_view params_[kMaxParams];  // views of string literals
  size_t count_ = 0;
  const Value* bound_[kMaxParams] = {};
};

}  // namespace smachac::tmpl
