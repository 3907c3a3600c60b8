// The filter/test/global registry (see builtins.h).
#include "backends/tmpl/filters/builtins.h"

#include "backends/tmpl/values/value_ops.h"

namespace smachac::tmpl {

Registry::Registry() : globals_(Value::newDict()) {
  registerStringFilters(*this);
  registerSequenceFilters(*this);
  registerNumberFilters(*this);
  registerBuiltinTests(*this);
  registerBuiltinGlobals(*this);
  registerSmachaExtensions(*this);
}

const FilterDef* Registry::filter(std::string_view name) const {
  auto it = filters_.find(name);
  return it == filters_.end() ? nullptr : &it->second;
}

const TestDef* Registry::test(std::string_view name) const {
  auto it = tests_.find(name);
  return it == tests_.end() ? nullptr : &it->second;
}

const Value* Registry::global(std::string_view name) const {
  return globals_.dict().findString(name);
}

std::vector<std::string_view> Registry::filterNames() const {
  std::vector<std::string_view> out;
  for (const auto& entry : filters_) out.push_back(entry.first);
  return out;
}

std::vector<std::string_view> Registry::testNames() const {
  std::vector<std::string_view> out;
  for (const auto& entry : tests_) out.push_back(entry.first);
  return out;
}

void Registry::addFilter(std::string name, FilterFn fn, FilterIntoFn into) {
  FilterDef& def = filters_[name];
  def = FilterDef{name, fn, {}, into};
}

void Registry::addTest(std::string name, TestFn fn) {
  TestDef& def = tests_[name];
  def = TestDef{name, fn, {}};
}

void Registry::addFilter(std::string name, CustomFilter fn) {
  FilterDef& def = filters_[name];
  def = FilterDef{name, nullptr, std::move(fn), nullptr};
}

void Registry::addTest(std::string name, CustomTest fn) {
  TestDef& def = tests_[name];
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
