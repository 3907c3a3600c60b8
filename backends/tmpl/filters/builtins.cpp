// The process-wide table of built-in filters and tests, and the registry of an environment
// (see builtins.h).
#include "backends/tmpl/filters/builtins.h"

#include <algorithm>
#include <cassert>
#include <iterator>

#include "backends/tmpl/values/value_ops.h"

namespace smachac::tmpl {

namespace {

/// FNV-1a over the name's bytes.
size_t nameHash(std::string_view name) {
  uint32_t hash = 2166136261u;
  for (char c : name) hash = (hash ^ static_cast<unsigned char>(c)) * 16777619u;
  return hash;
}

/// The slot that holds `name`, or the empty slot where it would go.
template <typename Slots, typename Def>
size_t slotOf(const Slots& slots, const std::vector<Def>& defs, std::string_view name) {
  size_t slot = nameHash(name) & (slots.size() - 1);
  while (slots[slot] != 0 && defs[slots[slot] - 1].name != name) {
    slot = (slot + 1) & (slots.size() - 1);
  }
  return slot;
}

/// Indexes every definition in order: a later one of a name takes the earlier one's slot.
template <typename Slots, typename Def>
void indexAll(Slots& slots, const std::vector<Def>& defs) {
  assert(defs.size() * 2 <= slots.size());
  for (size_t i = 0; i < defs.size(); ++i) {
    slots[slotOf(slots, defs, defs[i].name)] = static_cast<uint16_t>(i + 1);
  }
}

template <typename Slots, typename Def>
const Def* findByName(const Slots& slots, const std::vector<Def>& defs, std::string_view name) {
  uint16_t entry = slots[slotOf(slots, defs, name)];
  return entry == 0 ? nullptr : &defs[entry - 1];
}

/// The indexed names, sorted.
template <typename Slots, typename Def>
std::vector<std::string_view> namesOf(const Slots& slots, const std::vector<Def>& defs) {
  std::vector<std::string_view> out;
  for (uint16_t entry : slots) {
    if (entry != 0) out.push_back(defs[entry - 1].name);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The sorted union of two sorted name lists.
std::vector<std::string_view> mergedNames(std::vector<std::string_view> builtin,
                                          std::vector<std::string_view> custom) {
  std::vector<std::string_view> out;
  std::set_union(builtin.begin(), builtin.end(), custom.begin(), custom.end(),
                 std::back_inserter(out));
  return out;
}

}  // namespace

BuiltinTable::BuiltinTable() {
  filters_.reserve(kSlots / 2);
  tests_.reserve(kSlots / 2);
}

void BuiltinTable::addFilter(std::string_view name, FilterFn fn, FilterIntoFn into) {
  FilterDef& def = filters_.emplace_back();
  def.name = name;
  def.fn = fn;
  def.into = into;
}

void BuiltinTable::addTest(std::string_view name, TestFn fn) {
  TestDef& def = tests_.emplace_back();
  def.name = name;
  def.fn = fn;
}

void BuiltinTable::seal() {
  indexAll(filter_slots_, filters_);
  indexAll(test_slots_, tests_);
}

const FilterDef* BuiltinTable::filter(std::string_view name) const {
  return findByName(filter_slots_, filters_, name);
}

const TestDef* BuiltinTable::test(std::string_view name) const {
  return findByName(test_slots_, tests_, name);
}

std::vector<std::string_view> BuiltinTable::filterNames() const {
  return namesOf(filter_slots_, filters_);
}

std::vector<std::string_view> BuiltinTable::testNames() const {
  return namesOf(test_slots_, tests_);
}

const BuiltinTable& builtinTable() {
  static const BuiltinTable kTable = [] {
    BuiltinTable t;
    registerStringFilters(t);
    registerSequenceFilters(t);
    registerNumberFilters(t);
    registerBuiltinTests(t);
    registerSmachaExtensions(t);
    t.seal();
    return t;
  }();
  return kTable;
}

Registry::Registry() : builtins_(builtinTable()), globals_(Value::newDict()) {
  registerBuiltinGlobals(*this);
}

const FilterDef* Registry::filter(std::string_view name) const {
  if (!custom_filters_.empty()) {
    if (auto it = custom_filters_.find(name); it != custom_filters_.end()) return &it->second;
  }
  return builtins_.filter(name);
}

const TestDef* Registry::test(std::string_view name) const {
  if (!custom_tests_.empty()) {
    if (auto it = custom_tests_.find(name); it != custom_tests_.end()) return &it->second;
  }
  return builtins_.test(name);
}

const Value* Registry::global(std::string_view name) const {
  return globals_.dict().findString(name);
}

const Value* Registry::global(std::string_view name, size_t hash) const {
  return globals_.dict().findString(name, hash);
}

std::vector<std::string_view> Registry::filterNames() const {
  std::vector<std::string_view> custom;
  for (const auto& entry : custom_filters_) custom.push_back(entry.first);
  return mergedNames(builtins_.filterNames(), std::move(custom));
}

std::vector<std::string_view> Registry::testNames() const {
  std::vector<std::string_view> custom;
  for (const auto& entry : custom_tests_) custom.push_back(entry.first);
  return mergedNames(builtins_.testNames(), std::move(custom));
}

void Registry::addFilter(std::string name, CustomFilter fn) {
  FilterDef& def = custom_filters_[name];
  def = FilterDef{name, nullptr, std::move(fn), nullptr};
}

void Registry::addTest(std::string name, CustomTest fn) {
  TestDef& def = custom_tests_[name];
  def = TestDef{name, nullptr, std::move(fn)};
}

void Registry::addGlobal(std::string name, Value value) {
  globals_.dict().setString(name, std::move(value));
}

Value applyFilter(Exec& ex, const FilterDef& def, const Value& input, const CallArgs& args) {
  if (def.fn) return def.fn(ex, input, args);
  return def.custom(input, args);
}

bool applyTest(Exec& ex, const TestDef& def, const Value& input, const CallArgs& args) {
  if (def.fn) return def.fn(ex, input, args);
  return def.custom(input, args);
}

}  // namespace smachac::tmpl
