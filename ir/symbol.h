// An interned string: the names of the IR (states, outcomes, keys, templates). Each distinct
// text is kept once per process and never freed, and a Symbol is one pointer to it, so a name
// is 8 bytes instead of a 32-byte string, and copying one costs a pointer. Interning is
// thread-safe (the language server checks on several threads).
//
// Rules: a Symbol is made from any string and reads as a `const std::string&` and as a
// `std::string_view`, implicitly both ways (a name's text was a std::string); two Symbols are
// equal when their texts are, and order by text (so output that sorts names stays the same).
// For the rest of std::string's interface, `str()`.
#pragma once

#include <fmt/format.h>

#include <compare>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace smachac::ir {

class Symbol {
 public:
  Symbol();
  Symbol(std::string_view text) : text_(intern(text)) {}
  Symbol(const std::string& text) : text_(intern(text)) {}
  Symbol(const char* text) : text_(intern(text)) {}

  const std::string& str() const { return *text_; }
  operator const std::string&() const { return *text_; }
  operator std::string_view() const { return *text_; }

  bool empty() const { return text_->empty(); }
  size_t size() const { return text_->size(); }
  const char* data() const { return text_->data(); }
  std::string::const_iterator begin() const { return text_->begin(); }
  std::string::const_iterator end() const { return text_->end(); }
  char front() const { return text_->front(); }
  char back() const { return text_->back(); }
  char operator[](size_t i) const { return (*text_)[i]; }

  friend bool operator==(const Symbol& a, const Symbol& b) { return a.text_ == b.text_; }
  friend bool operator==(const Symbol& a, const std::string& b) { return *a.text_ == b; }
  friend bool operator==(const Symbol& a, std::string_view b) { return *a.text_ == b; }
  friend bool operator==(const Symbol& a, const char* b) { return *a.text_ == b; }
  friend std::strong_ordering operator<=>(const Symbol& a, const Symbol& b) {
    return a.text_ == b.text_ ? std::strong_ordering::equal : *a.text_ <=> *b.text_;
  }
  friend std::strong_ordering operator<=>(const Symbol& a, const std::string& b) {
    return *a.text_ <=> b;
  }
  friend std::strong_ordering operator<=>(const Symbol& a, std::string_view b) {
    return std::string_view(*a.text_) <=> b;
  }
  friend std::string operator+(const Symbol& a, std::string_view b) {
    std::string joined = *a.text_;
    joined += b;
    return joined;
  }
  friend std::string operator+(const Symbol& a, const std::string& b) { return *a.text_ + b; }
  friend std::string operator+(const Symbol& a, const char* b) { return *a.text_ + b; }
  friend std::string operator+(const Symbol& a, char b) { return *a.text_ + b; }
  friend std::string operator+(const std::string& a, const Symbol& b) { return a + *b.text_; }
  friend std::string operator+(const char* a, const Symbol& b) { return a + *b.text_; }
  friend std::string operator+(char a, const Symbol& b) { return a + *b.text_; }

 private:
  static const std::string* intern(std::string_view text);

  const std::string* text_;
};

}  // namespace smachac::ir

template <>
struct std::hash<smachac::ir::Symbol> {
  size_t operator()(const smachac::ir::Symbol& s) const noexcept {
    return std::hash<std::string_view>()(s);
  }
};

template <>
struct fmt::formatter<smachac::ir::Symbol> : fmt::formatter<std::string_view> {
  template <class FormatContext>
  auto format(const smachac::ir::Symbol& s, FormatContext& ctx) const {
    return fmt::formatter<std::string_view>::format(std::string_view(s), ctx);
  }
};
