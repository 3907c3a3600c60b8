// Arguments of a call (positional and keyword), and ArgBinder, which binds them to a Python-like
// parameter list for built-in filters, tests, methods and globals.
#pragma once

#include <initializer_list>
#include <new>
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
/// The inline room is raw storage: only the elements added are constructed and destroyed
/// (every call's arguments, every render's Exec makes some).
template <class T, size_t N>
class SmallVector {
 public:
  SmallVector() = default;
  SmallVector(const SmallVector& other) { append(other); }
  SmallVector(SmallVector&& other) noexcept { take(std::move(other)); }
  SmallVector& operator=(const SmallVector& other) {
    if (this != &other) {
      clear();
      append(other);
    }
    return *this;
  }
  SmallVector& operator=(SmallVector&& other) noexcept {
    if (this != &other) {
      clear();
      take(std::move(other));
    }
    return *this;
  }
  ~SmallVector() { destroyInline(); }

  template <class... Args>
  void emplaceBack(Args&&... args) {
    if (heap_.empty() && size_ < N) {
      new (inlineData() + size_) T(std::forward<Args>(args)...);
      ++size_;
      return;
    }
    if (heap_.empty()) spill();
    heap_.emplace_back(std::forward<Args>(args)...);
  }
  void pushBack(T value) { emplaceBack(std::move(value)); }
  void reserve(size_t) {}
  void clear() {
    destroyInline();
    heap_.clear();
  }
  const T* data() const { return heap_.empty() ? inlineData() : heap_.data(); }
  T* data() { return heap_.empty() ? inlineData() : heap_.data(); }
  size_t size() const { return heap_.empty() ? size_ : heap_.size(); }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size(); }
  T* begin() { return data(); }
  T* end() { return data() + size(); }
  T& operator[](size_t i) { return data()[i]; }
  const T& operator[](size_t i) const { return data()[i]; }
  operator std::span<const T>() const { return {data(), size()}; }  // NOLINT

 private:
  T* inlineData() { return std::launder(reinterpret_cast<T*>(storage_)); }
  const T* inlineData() const { return std::launder(reinterpret_cast<const T*>(storage_)); }
  void destroyInline() {
    for (size_t i = 0; i < size_; ++i) inlineData()[i].~T();
    size_ = 0;
  }
  // Moves the inline elements to the heap (which then holds every element).
  void spill() {
    heap_.reserve(N * 2);
    for (size_t i = 0; i < size_; ++i) heap_.push_back(std::move(inlineData()[i]));
    destroyInline();
  }
  void append(const SmallVector& other) {
    for (const T& item : other) emplaceBack(item);
  }
  // The elements of `other`, into an empty vector: its heap taken whole, or its inline
  // elements moved (they fit), so nothing is allocated.
  void take(SmallVector&& other) noexcept {
    if (!other.heap_.empty()) {
      heap_ = std::move(other.heap_);
      other.heap_.clear();
      return;
    }
    for (size_t i = 0; i < other.size_; ++i)
      new (inlineData() + i) T(std::move(other.inlineData()[i]));
    size_ = other.size_;
    other.destroyInline();
  }

  alignas(T) unsigned char storage_[N * sizeof(T)];
  size_t size_ = 0;  // constructed inline elements (0 once spilled)
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
  // Inline for the common cases (absent, an int or a bool): every `indent` reads three.
  int64_t getInt(size_t index, int64_t fallback) const {
    const Value* v = bound_[index];
    if (!v) return fallback;
    if (v->isInt() || v->isBool()) return v->integral();
    failNotInt(index);
  }
  bool getBool(size_t index, bool fallback) const {
    const Value* v = bound_[index];
    if (!v) return fallback;
    if (v->isBool()) return v->b();
    return truthyOf(*v);
  }

 private:
  static constexpr size_t kMaxParams = 8;
  // A parameter's name: a view of a string literal, stored without a constructor so that only
  // the `count_` names given are written (a filter call makes a binder).
  struct ParamName {
    const char* data;
    size_t size;
    std::string_view view() const { return {data, size}; }
  };
  [[noreturn]] void failKeyword(const std::string& name, bool duplicate) const;
  [[noreturn]] void failNotInt(size_t index) const;
  static bool truthyOf(const Value& v);
  std::string_view function_;
  ParamName params_[kMaxParams];
  size_t count_ = 0;
  const Value* bound_[kMaxParams] = {};
};

}  // namespace smachac::tmpl
