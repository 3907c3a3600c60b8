// The registry of filters, tests and globals (built-in and custom) that templates are parsed
// and rendered against, and the functions that fill it with the built-ins.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "backends/tmpl/renderer/call_args.h"
#include "backends/tmpl/values/value.h"

namespace smachac::tmpl {

using FilterFn = Value (*)(Exec& ex, const Value& input, const CallArgs& args);
/// A filter's result appended straight to `out` (what `{{ x | f }}` prints), with the same
/// result and errors as its FilterFn; false when it leaves this input to the FilterFn.
using FilterIntoFn = bool (*)(Exec& ex, const Value& input, const CallArgs& args, std::string& out);
using TestFn = bool (*)(Exec& ex, const Value& input, const CallArgs& args);
using CustomFilter = std::function<Value(const Value& input, const CallArgs& args)>;
using CustomTest = std::function<bool(const Value& input, const CallArgs& args)>;

struct FilterDef {
  std::string name;
  FilterFn fn = nullptr;
  CustomFilter custom;
  FilterIntoFn into = nullptr;  ///< optional, built-in filters only
};

struct TestDef {
  std::string name;
  TestFn fn = nullptr;
  CustomTest custom;
};

class Registry {
 public:
  Registry();
  const FilterDef* filter(std::string_view name) const;
  const TestDef* test(std::string_view name) const;
  const Value* global(std::string_view name) const;
  std::vector<std::string_view> filterNames() const;
  std::vector<std::string_view> testNames() const;

  void addFilter(std::string name, FilterFn fn, FilterIntoFn into = nullptr);
  void addTest(std::string name, TestFn fn);
  void addFilter(std::string name, CustomFilter fn);
  void addTest(std::string name, CustomTest fn);
  void addGlobal(std::string name, Value value);

 private:
  // std::map keeps the definitions at stable addresses (the AST points at them).
  std::map<std::string, FilterDef, std::less<>> filters_;
  std::map<std::string, TestDef, std::less<>> tests_;
  Value globals_;  // a dict
};

void registerStringFilters(Registry& r);
void registerSequenceFilters(Registry& r);
void registerNumberFilters(Registry& r);
void registerBuiltinTests(Registry& r);
void registerBuiltinGlobals(Registry& r);
void registerSmachaExtensions(Registry& r);
void registerSelectFilters(Registry& r);

/// Calls a filter or a test by definition.
Value applyFilter(Exec& ex, const FilterDef& def, const Value& input, const CallArgs& args);
bool applyTest(Exec& ex, const TestDef& def, const Value& input, const CallArgs& args);

}  // namespace smachac::tmpl
