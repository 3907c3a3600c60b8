// Value construction, reference counting, interning and the dict's hash index.
#include "backends/tmpl/values/value.h"

#include <cstring>
#include <mutex>
#include <unordered_set>

#include "backends/tmpl/error.h"
#include "backends/tmpl/limits.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::tmpl {

namespace {

// Looks strings up by view, so that finding an interned name allocates nothing.
struct ViewHash {
  using is_transparent = void;  // NOLINT(readability-identifier-naming): the standard name
  size_t operator()(std::string_view s) const { return std::hash<std::string_view>()(s); }
};

// Where `s` goes in the per-thread cache of interned names: its size and three of its bytes.
size_t internCacheSlot(std::string_view s) {
  if (s.empty()) return 0;
  auto byte = [&](size_t i) { return static_cast<size_t>(static_cast<unsigned char>(s[i])); };
  return (s.size() ^ byte(0) << 1 ^ byte(s.size() / 2) << 3 ^ byte(s.size() - 1) << 5) & 63;
}

}  // namespace

const std::string* intern(std::string_view s) {
  // Recent names per thread, in front of the locked and hashed pool: a render interns the
  // same few names (block names, keyword arguments) over and over.
  thread_local const std::string* recent[64] = {};
  const std::string*& cached = recent[internCacheSlot(s)];
  if (cached && *cached == s) return cached;
  static std::mutex mutex;
  // Never freed: the pointers escape into compiled templates and values.
  static auto* pool = new std::unordered_set<std::string, ViewHash, std::equal_to<>>();
  std::lock_guard<std::mutex> lock(mutex);
  auto found = pool->find(s);
  cached = found != pool->end() ? &*found : &*pool->emplace(s).first;
  return cached;
}

namespace {

// A render creates and frees thousands of small objects (strings, lists, loop objects,
// contexts); malloc's per-thread cache holds only a few blocks of each size, so they are
// recycled here, by 16-byte size class, up to kPoolDepth blocks per class.
constexpr size_t kPoolGranule = 16;
constexpr size_t kPoolClasses = 8;
constexpr uint32_t kPoolDepth = 512;

struct FreeBlock {
  FreeBlock* next;
};

struct ObjectPool {
  FreeBlock* heads[kPoolClasses] = {};
  uint32_t counts[kPoolClasses] = {};
  ~ObjectPool() {
    for (size_t i = 0; i < kPoolClasses; ++i) {
      while (FreeBlock* block = heads[i]) {
        heads[i] = block->next;
        ::operator delete(block);
      }
      counts[i] = kPoolDepth;  // objects freed after this (static values) go to malloc
    }
  }
};

thread_local ObjectPool object_pool;

size_t poolClass(size_t size) { return (size + kPoolGranule - 1) / kPoolGranule - 1; }

}  // namespace

void* Object::operator new(size_t size) {
  size_t cls = poolClass(size);
  if (cls >= kPoolClasses) return ::operator new(size);
  ObjectPool& pool = object_pool;
  if (FreeBlock* block = pool.heads[cls]) {
    pool.heads[cls] = block->next;
    --pool.counts[cls];
    return block;
  }
  return ::operator new((cls + 1) * kPoolGranule);
}

void Object::operator delete(void* memory, size_t size) noexcept {
  size_t cls = poolClass(size);
  if (cls >= kPoolClasses) return ::operator delete(memory);
  ObjectPool& pool = object_pool;
  if (pool.counts[cls] >= kPoolDepth) return ::operator delete(memory);
  auto* block = static_cast<FreeBlock*>(memory);
  block->next = pool.heads[cls];
  pool.heads[cls] = block;
  ++pool.counts[cls];
}

void Object::destroy(const Object* object) noexcept {
  // Children released by a destructor are queued instead of deleted recursively.
  thread_local std::vector<const Object*> pending;
  thread_local bool active = false;
  if (active) {
    pending.push_back(object);
    return;
  }
  active = true;
  delete object;
  while (!pending.empty()) {
    const Object* next = pending.back();
    pending.pop_back();
    delete next;
  }
  active = false;
}

void Object::repr(std::string& out) const {
  out += "<";
  out += typeName();
  out += " object>";
}

bool Object::getAttr(std::string_view, Value&) const { return false; }

bool Object::iterate(std::vector<Value>&) const { return false; }

Value Object::call(Exec&, const CallArgs&) const {
  fail("`" + std::string(typeName()) + "` object is not callable");
}

Value Value::boolean(bool b) {
  Value v;
  v.kind_ = Kind::Bool;
  v.b_ = b;
  return v;
}

Value Value::integer(int64_t i) {
  Value v;
  v.kind_ = Kind::Int;
  v.i_ = i;
  return v;
}

Value Value::real(double d) {
  Value v;
  v.kind_ = Kind::Float;
  v.f_ = d;
  return v;
}

Value Value::string(std::string text, bool markup) {
  chargeWork(text.size());
  return string(new StringObject(std::move(text)), markup);
}

Value Value::string(const StringObject* text, bool markup) {
  Value v;
  v.kind_ = Kind::String;
  v.flags_ = markup ? 1 : 0;
  v.obj_ = text;
  text->retain();
  return v;
}

Value Value::newList(std::vector<Value> items) {
  chargeWork(items.size() * sizeof(Value));
  Value v = object(new ListObject(std::move(items)));
  v.kind_ = Kind::List;
  return v;
}

Value Value::newTuple(std::vector<Value> items) {
  Value v = newList(std::move(items));
  v.kind_ = Kind::Tuple;
  return v;
}

Value Value::newDict() {
  Value v = object(new DictObject());
  v.kind_ = Kind::Dict;
  return v;
}

Value Value::object(const Object* object) {
  Value v;
  v.kind_ = Kind::Object;
  v.obj_ = object;
  object->retain();
  return v;
}

Value Value::undefinedAttribute(const Value& owner, const std::string* attribute) {
  Value v;
  v.flags_ = kAttribute;
  v.aux_ = static_cast<uint8_t>(owner.kind());
  v.name_ = attribute;
  return v;
}

Value Value::undefinedHint(std::string message) {
  Value v;
  v.flags_ = kHint;
  v.obj_ = new StringObject(std::move(message));
  v.obj_->retain();
  return v;
}

const std::string& Value::s() const { return static_cast<const StringObject*>(obj_)->text(); }

const StringObject* Value::stringObject() const { return static_cast<const StringObject*>(obj_); }

ListObject& Value::list() const {
  return *const_cast<ListObject*>(static_cast<const ListObject*>(obj_));
}

DictObject& Value::dict() const {
  return *const_cast<DictObject*>(static_cast<const DictObject*>(obj_));
}

std::string Value::undefinedMessage() const {
  switch (flags_) {
    case kName:
    case kMissing:
      return "`" + *name_ + "` is undefined";
    case kAttribute: {
      return "`" + std::string(kindName(static_cast<Kind>(aux_))) + "` object has no attribute `" +
             *name_ + "`";
    }
    case kHint:
      return static_cast<const StringObject*>(obj_)->text();
    default:
      return "undefined value";
  }
}

Value Value::withMarkup(bool markup) const {
  Value v(*this);
  if (v.kind_ == Kind::String) v.flags_ = markup ? 1 : 0;
  return v;
}

// Eight bytes a step (names and keys are 4 to 20 bytes), each word mixed in by a multiply and
// a shift; the final mix spreads every byte into the low bits the dict's table uses.
size_t hashString(std::string_view s) {
  constexpr uint64_t kMul = 0xff51afd7ed558ccdull;
  uint64_t h = 0x9e3779b97f4a7c15ull ^ s.size();
  const char* p = s.data();
  size_t n = s.size();
  for (; n >= 8; p += 8, n -= 8) {
    uint64_t word;
    std::memcpy(&word, p, sizeof word);
    h = (h ^ word) * kMul;
    h ^= h >> 32;
  }
  uint64_t tail = 0;
  for (size_t i = 0; i < n; ++i) tail |= uint64_t{static_cast<unsigned char>(p[i])} << (8 * i);
  h = (h ^ tail) * kMul;
  h ^= h >> 29;
  h *= kMul;
  h ^= h >> 32;
  return static_cast<size_t>(h | 1);  // never 0, so 0 can mean "not computed"
}

size_t StringObject::hash() const {
  if (hash_ == 0) hash_ = hashString(text_);
  return hash_;
}

// --- DictObject ---------------------------------------------------------------------------

namespace {
constexpr size_t kLinearLimit = 8;
}  // namespace

size_t DictObject::slotOf(const Value& key, size_t hash) const {
  if (table_.empty()) {
    for (size_t i = 0; i < entries_.size(); ++i) {
      if (hashes_[i] == hash && equals(entries_[i].first, key)) return i;
    }
    return SIZE_MAX;
  }
  size_t mask = table_.size() - 1;
  for (size_t probe = hash & mask;; probe = (probe + 1) & mask) {
    uint32_t slot = table_[probe];
    if (slot == 0) return SIZE_MAX;
    if (hashes_[slot - 1] == hash && equals(entries_[slot - 1].first, key)) return slot - 1;
  }
}

size_t DictObject::slotOfString(std::string_view key, size_t hash) const {
  auto matches = [&](size_t i) {
    const Value& k = entries_[i].first;
    return hashes_[i] == hash && k.isString() && sameText(k.s(), key);
  };
  if (table_.empty()) {
    for (size_t i = 0; i < entries_.size(); ++i) {
      if (matches(i)) return i;
    }
    return SIZE_MAX;
  }
  size_t mask = table_.size() - 1;
  for (size_t probe = hash & mask;; probe = (probe + 1) & mask) {
    uint32_t slot = table_[probe];
    if (slot == 0) return SIZE_MAX;
    if (matches(slot - 1)) return slot - 1;
  }
}

const Value* DictObject::find(const Value& key) const {
  size_t i = slotOf(key, hashOf(key));
  return i == SIZE_MAX ? nullptr : &entries_[i].second;
}

const Value* DictObject::findString(std::string_view key) const {
  return findString(key, hashString(key));
}

const Value* DictObject::findString(std::string_view key, size_t hash) const {
  size_t i = slotOfString(key, hash);
  return i == SIZE_MAX ? nullptr : &entries_[i].second;
}

void DictObject::set(const Value& key, Value value) {
  size_t hash = hashOf(key);
  size_t i = slotOf(key, hash);
  if (i != SIZE_MAX) {
    entries_[i].second = std::move(value);
    return;
  }
  append(key.loaded(), std::move(value), hash);
}

void DictObject::setString(std::string_view key, Value value) {
  size_t hash = hashString(key);
  size_t i = slotOfString(key, hash);
  if (i != SIZE_MAX) {
    entries_[i].second = std::move(value);
    return;
  }
  // The key is made in place, carrying the hash just computed: no string moved through
  // Value::string, and StringObject::hash, asked later of the key (a lookup or a copy by its
  // Value), is known already.
  chargeWork(key.size());
  append(Value::string(new StringObject(key, hash)), std::move(value), hash);
}

void DictObject::update(const DictObject& from) {
  reserve(entries_.size() + from.entries_.size());
  for (size_t i = 0; i < from.entries_.size(); ++i) {
    const auto& [key, value] = from.entries_[i];
    size_t at = slotOf(key, from.hashes_[i]);
    if (at != SIZE_MAX) {
      entries_[at].second = value;
    } else {
      append(key, value, from.hashes_[i]);
    }
  }
}

void DictObject::reserve(size_t count) {
  entries_.reserve(count);
  hashes_.reserve(count);
}

void DictObject::append(Value key, Value value, size_t hash) {
  if (entries_.size() == entries_.capacity()) {
    // Most dicts are small: room for 4 entries, then 16 (a render context of a dozen keys
    // grows once, not twice), then doubling.
    size_t room = entries_.capacity();
    room = room == 0 ? 4 : room < 16 ? room * 4 : room * 2;
    entries_.reserve(room);
    hashes_.reserve(room);
  }
  entries_.emplace_back(std::move(key), std::move(value));
  hashes_.push_back(hash);
  ++shape_;
  if (entries_.size() > kLinearLimit && entries_.size() * 2 > table_.size()) {
    rebuildIndex();
    return;
  }
  if (!table_.empty()) {
    size_t mask = table_.size() - 1;
    size_t probe = hash & mask;
    while (table_[probe] != 0) probe = (probe + 1) & mask;
    table_[probe] = static_cast<uint32_t>(entries_.size());
  }
}

bool DictObject::erase(const Value& key, Value* removed) {
  size_t i = slotOf(key, hashOf(key));
  if (i == SIZE_MAX) return false;
  if (removed) *removed = std::move(entries_[i].second);
  entries_.erase(entries_.begin() + static_cast<std::ptrdiff_t>(i));
  hashes_.erase(hashes_.begin() + static_cast<std::ptrdiff_t>(i));
  ++shape_;
  rebuildIndex();
  return true;
}

void DictObject::clear() {
  entries_.clear();
  hashes_.clear();
  table_.clear();
  ++shape_;
}

void DictObject::rebuildIndex() {
  table_.clear();
  if (entries_.size() <= kLinearLimit) return;
  size_t capacity = 16;
  while (capacity < entries_.size() * 4) capacity *= 2;
  table_.assign(capacity, 0);
  size_t mask = capacity - 1;
  for (size_t i = 0; i < entries_.size(); ++i) {
    size_t probe = hashes_[i] & mask;
    while (table_[probe] != 0) probe = (probe + 1) & mask;
    table_[probe] = static_cast<uint32_t>(i + 1);
  }
}

}  // namespace smachac::tmpl
