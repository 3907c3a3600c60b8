// The registry of filters, tests and globals (built-in and custom) that templates are parsed
// and rendered against, and the functions that fill the built-in table. The built-in filters
// and tests are one table for the whole process, made at first use (an environment used to
// build its own: ~70 K instructions of a cold compile); an environment's registry holds only
// its custom ones and its globals, and a custom definition hides a built-in of its name.
#pragma once

#include <array>
#include <cstdint>
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

/// The built-in filters and tests: filled once, then sealed and never changed (the AST points
/// at its definitions). Of two definitions of one name, the later one counts.
class BuiltinTable {
 public:
  BuiltinTable();
  void addFilter(std::string_view name, FilterFn fn, FilterIntoFn into = nullptr);
  void addTest(std::string_view name, TestFn fn);
  /// Indexes the names for lookup; nothing is added afterwards.
  void seal();

  const FilterDef* filter(std::string_view name) const;
  const TestDef* test(std::string_view name) const;
  /// The sorted names.
  std::vector<std::string_view> filterNames() const;
  std::vector<std::string_view> testNames() const;

 private:
  /// Open-addressing hash slots over a table's names: 1 + an index into it, 0 when empty.
  static constexpr size_t kSlots = 256;  // a power of two, at least twice the definitions
  using Slots = std::array<uint16_t, kSlots>;

  std::vector<FilterDef> filters_;
  std::vector<TestDef> tests_;
  Slots filter_slots_{};
  Slots test_slots_{};
};

/// The process's built-in table, made at the first call (thread-safe).
const BuiltinTable& builtinTable();

class Registry {
 public:
  Registry();
  const FilterDef* filter(std::string_view name) const;
  const TestDef* test(std::string_view name) const;
  const Value* global(std::string_view name) const;
  /// The same with the name's hash (`hashString`), as frames keep it for context lookups.
  const Value* global(std::string_view name, size_t hash) const;
  std::vector<std::string_view> filterNames() const;
  std::vector<std::string_view> testNames() const;

  void addFilter(std::string name, CustomFilter fn);
  void addTest(std::string name, CustomTest fn);
  void addGlobal(std::string name, Value value);

 private:
  const BuiltinTable& builtins_;
  // std::map keeps the definitions at stable addresses (the AST points at them).
  std::map<std::string, FilterDef, std::less<>> custom_filters_;
  std::map<std::string, TestDef, std::less<>> custom_tests_;
  Value globals_;  // a dict
};

void registerStringFilters(BuiltinTable& r);
void registerSequenceFilters(BuiltinTable& r);
void registerNumberFilters(BuiltinTable& r);
void registerBuiltinTests(BuiltinTable& r);
void registerBuiltinGlobals(Registry& r);
void registerSmachaExtensions(BuiltinTable& r);
void registerSelectFilters(BuiltinTable& r);

/// Calls a filter or a test by definition.
Value applyFilter(Exec& ex, const FilterDef& def, const Value& input, const CallArgs& args);
bool applyTest(Exec& ex, const TestDef& def, const Value& input, const CallArgs& args);

}  // namespace smachac::tmpl
