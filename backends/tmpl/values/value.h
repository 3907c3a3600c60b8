// Values of the template language: Python-like dynamic values (undefined, None, bool, int,
// float, str, list, tuple, dict and callable objects). Strings are immutable and shared;
// lists and dicts are shared by reference (copying a Value never copies the container), which
// SMACHA's `defined_headers` de-duplication relies on. Not thread-safe: one Environment and
// its values belong to one thread at a time.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace smachac::tmpl {

class Value;
class Exec;
struct CallArgs;

/// Interns `s` in a process-wide pool; the pointer stays valid for the life of the process.
const std::string* intern(std::string_view s);

/// Base of every heap value. Reference counted (not atomically); the last release deletes it
/// without recursion, so arbitrarily deep structures can be freed safely.
class Object {
 public:
  Object() = default;
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  virtual ~Object() = default;
  /// Objects of up to 128 bytes are recycled through per-thread free lists (see value.cpp).
  static void* operator new(size_t size);
  static void* operator new(size_t, void* memory) noexcept { return memory; }
  static void operator delete(void* memory, size_t size) noexcept;

  void retain() const noexcept { ++refs_; }
  /// Whether more than one reference holds the object.
  bool shared() const noexcept { return refs_ > 1; }
  void release() const noexcept {
    if (--refs_ == 0) destroy(this);
  }

  // The protocol of Kind::Object values (macros, loop, modules, methods).
  virtual std::string_view typeName() const { return "object"; }
  virtual void repr(std::string& out) const;
  virtual void str(std::string& out) const { repr(out); }
  /// Sets `out` and returns true if the object has attribute `name`.
  virtual bool getAttr(std::string_view name, Value& out) const;
  virtual bool isCallable() const { return false; }
  virtual Value call(Exec& ex, const CallArgs& args) const;
  /// Appends what iterating the object yields and returns true, or false if not iterable.
  virtual bool iterate(std::vector<Value>& out) const;

 private:
  static void destroy(const Object* object) noexcept;
  mutable uint32_t refs_ = 0;
};

/// An owning, intrusive reference to an Object.
template <class T>
class Ref {
 public:
  Ref() = default;
  Ref(T* p) : p_(p) {  // NOLINT(google-explicit-constructor)
    if (p_) p_->retain();
  }
  Ref(const Ref& other) : Ref(other.p_) {}
  Ref(Ref&& other) noexcept : p_(other.p_) { other.p_ = nullptr; }
  ~Ref() {
    if (p_) p_->release();
  }
  Ref& operator=(Ref other) noexcept {
    std::swap(p_, other.p_);
    return *this;
  }
  T* get() const { return p_; }
  T* operator->() const { return p_; }
  T& operator*() const { return *p_; }
  explicit operator bool() const { return p_ != nullptr; }

 private:
  T* p_ = nullptr;
};

template <class T, class... Args>
Ref<T> makeRef(Args&&... args) {
  return Ref<T>(new T(std::forward<Args>(args)...));
}

enum class Kind : uint8_t {
  Undefined,
  None,
  Bool,
  Int,
  Float,
  String,
  List,
  Tuple,
  Dict,
  Object,
};

class StringObject;
class ListObject;
class DictObject;

class Value {
 public:
  Value() noexcept : kind_(Kind::Undefined), flags_(0), aux_(0), i_(0) {}
  Value(const Value& other) noexcept : kind_(other.kind_), flags_(other.flags_), aux_(other.aux_) {
    i_ = other.i_;
    if (counted()) obj_->retain();
  }
  Value(Value&& other) noexcept : kind_(other.kind_), flags_(other.flags_), aux_(other.aux_) {
    i_ = other.i_;
    other.kind_ = Kind::Undefined;
    other.flags_ = 0;
  }
  ~Value() {
    if (counted()) obj_->release();
  }
  // Assignments take the new value first and release the old one last: the old one may own
  // `other` (`v = v[0]`).
  Value& operator=(const Value& other) noexcept {
    if (other.counted()) other.obj_->retain();
    const Object* old = counted() ? obj_ : nullptr;
    kind_ = other.kind_;
    flags_ = other.flags_;
    aux_ = other.aux_;
    i_ = other.i_;
    if (old) old->release();
    return *this;
  }
  Value& operator=(Value&& other) noexcept {
    if (this == &other) return *this;
    const Object* old = counted() ? obj_ : nullptr;
    kind_ = other.kind_;
    flags_ = other.flags_;
    aux_ = other.aux_;
    i_ = other.i_;
    other.kind_ = Kind::Undefined;
    other.flags_ = 0;
    if (old) old->release();
    return *this;
  }
  void swap(Value& other) noexcept {
    std::swap(kind_, other.kind_);
    std::swap(flags_, other.flags_);
    std::swap(aux_, other.aux_);
    std::swap(i_, other.i_);
  }

  // The small constructors are inline: a render makes them by the thousand. (Not boolean and
  // integer: inlined, GCC 12 takes the number in the union for an Object's address in the
  // destructors after them and warns, -Warray-bounds.)
  static Value none() {
    Value v;
    v.kind_ = Kind::None;
    return v;
  }
  static Value boolean(bool b);
  static Value integer(int64_t i);
  static Value real(double d);
  static Value string(std::string text, bool markup = false);
  static Value string(const StringObject* text, bool markup = false);
  static Value newList(std::vector<Value> items = {});
  static Value newTuple(std::vector<Value> items);
  static Value newDict();
  static Value object(const Object* object);

  static Value undefined() { return Value(); }
  /// `name` is undefined (an unknown variable).
  static Value undefinedName(const std::string* name) {
    Value v;
    v.flags_ = kName;
    v.name_ = name;
    return v;
  }
  /// An unbound variable slot; loads turn it into undefinedName.
  static Value missing(const std::string* name) {
    Value v;
    v.flags_ = kMissing;
    v.name_ = name;
    return v;
  }
  /// `owner` has no attribute `attribute`.
  static Value undefinedAttribute(const Value& owner, const std::string* attribute);
  /// An undefined value that explains itself with `message` when used.
  static Value undefinedHint(std::string message);

  Kind kind() const { return kind_; }
  bool isUndefined() const { return kind_ == Kind::Undefined; }
  bool isMissing() const { return kind_ == Kind::Undefined && flags_ == kMissing; }
  bool isNone() const { return kind_ == Kind::None; }
  bool isBool() const { return kind_ == Kind::Bool; }
  bool isInt() const { return kind_ == Kind::Int; }
  bool isFloat() const { return kind_ == Kind::Float; }
  bool isNumber() const { return kind_ >= Kind::Bool && kind_ <= Kind::Float; }
  bool isString() const { return kind_ == Kind::String; }
  bool isMarkup() const { return kind_ == Kind::String && flags_ != 0; }
  bool isList() const { return kind_ == Kind::List; }
  bool isTuple() const { return kind_ == Kind::Tuple; }
  bool isListOrTuple() const { return kind_ == Kind::List || kind_ == Kind::Tuple; }
  bool isDict() const { return kind_ == Kind::Dict; }
  bool isObject() const { return kind_ == Kind::Object; }

  bool b() const { return b_; }
  int64_t i() const { return i_; }
  double f() const { return f_; }
  /// int/bool/float as a double.
  double number() const { return kind_ == Kind::Float ? f_ : kind_ == Kind::Int ? double(i_) : b_; }
  /// int/bool as an integer.
  int64_t integral() const { return kind_ == Kind::Int ? i_ : kind_ == Kind::Bool ? b_ : 0; }
  const std::string& s() const;
  const StringObject* stringObject() const;
  ListObject& list() const;
  DictObject& dict() const;
  const Object* object() const { return obj_; }
  /// Identity of the heap object (containers, strings, objects) or nullptr.
  const void* identity() const { return kind_ >= Kind::String ? obj_ : nullptr; }

  /// The message an operation on this undefined value reports.
  std::string undefinedMessage() const;
  /// A missing slot as an ordinary undefined value; other values unchanged.
  Value loaded() const { return isMissing() ? undefinedName(name_) : *this; }
  /// The same string marked safe (Markup) or not.
  Value withMarkup(bool markup) const;

 private:
  enum UndefinedFlag : uint8_t { kPlain, kName, kMissing, kAttribute, kHint };
  bool counted() const {
    return kind_ >= Kind::String || (kind_ == Kind::Undefined && flags_ == kHint);
  }

  Kind kind_;
  uint8_t flags_;  // string: markup; undefined: UndefinedFlag
  uint8_t aux_;    // undefined attribute: Kind of the owner
  // The members of an anonymous union count as public for clang-tidy; they are private here.
  union {
    bool b_;                   // NOLINT(readability-identifier-naming)
    int64_t i_;                // NOLINT(readability-identifier-naming)
    double f_;                 // NOLINT(readability-identifier-naming)
    const Object* obj_;        // NOLINT(readability-identifier-naming)
    const std::string* name_;  // NOLINT(readability-identifier-naming)
  };
};

class StringObject final : public Object {
 public:
  explicit StringObject(std::string text) : text_(std::move(text)) {}
  /// A copy of `text` whose hash (hashString) the caller has computed already.
  StringObject(std::string_view text, size_t hash) : text_(text), hash_(hash) {}
  const std::string& text() const { return text_; }
  size_t hash() const;

 private:
  std::string text_;
  mutable size_t hash_ = 0;
};

/// Storage of lists and tuples.
class ListObject final : public Object {
 public:
  explicit ListObject(std::vector<Value> items = {}) : items_(std::move(items)) {}
  std::vector<Value>& items() { return items_; }
  const std::vector<Value>& items() const { return items_; }

 private:
  std::vector<Value> items_;
};

/// An insertion-ordered dict with Python key semantics (1 == 1.0 == True is one key).
class DictObject final : public Object {
 public:
  using Entry = std::pair<Value, Value>;

  /// Raises Fault for unhashable keys (lists, dicts).
  const Value* find(const Value& key) const;
  const Value* findString(std::string_view key) const;
  const Value* findString(std::string_view key, size_t hash) const;
  void set(const Value& key, Value value);
  void setString(std::string_view key, Value value);
  /// Python's dict.update(from): sets every entry of `from` in its order, with the hashes
  /// `from` keeps (no key is hashed again).
  void update(const DictObject& from);
  /// Room for `count` entries in all, so that adding them moves no entry.
  void reserve(size_t count);
  bool erase(const Value& key, Value* removed = nullptr);
  void clear();
  size_t size() const { return entries_.size(); }
  bool empty() const { return entries_.empty(); }
  const std::vector<Entry>& entries() const { return entries_; }
  /// Version counter, bumped when keys are added or removed (iteration checks it).
  uint64_t shape() const { return shape_; }

 private:
  size_t slotOf(const Value& key, size_t hash) const;
  size_t slotOfString(std::string_view key, size_t hash) const;
  void rebuildIndex();
  void append(Value key, Value value, size_t hash);

  std::vector<Entry> entries_;
  std::vector<size_t> hashes_;
  std::vector<uint32_t> table_;  // open addressing: 0 empty, else entry index + 1
  uint64_t shape_ = 0;
};

size_t hashString(std::string_view s);

/// a == b for the short names and keys a render compares by the thousand (a dict key whose hash
/// matched, a cached block name): words compared inline where `==` calls memcmp.
inline bool sameText(std::string_view a, std::string_view b) {
  size_t n = a.size();
  if (n != b.size()) return false;
  auto word = [](const char* p) {
    uint64_t w;
    std::memcpy(&w, p, sizeof w);
    return w;
  };
  if (n >= 8) {
    for (size_t i = 0; i + 8 < n; i += 8) {
      if (word(a.data() + i) != word(b.data() + i)) return false;
    }
    return word(a.data() + n - 8) == word(b.data() + n - 8);  // the last 8, overlapping
  }
  for (size_t i = 0; i < n; ++i) {
    if (a[i] != b[i]) return false;
  }
  return true;
}

}  // namespace smachac::tmpl
