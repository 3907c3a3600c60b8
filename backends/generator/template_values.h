// IR values as template values (the view model's leaves):
//   null → None, bool, int, float, string → the same; list → list; map → dict (insertion order);
//   expression (`code` in the script) → the string "`code`" again, so that SMACHA's
//   `expression` test and `exptostr` filter work on it in templates.
// A value marked as a behavior parameter (ir::Value::behavior_param) whose reference the target
// registered with `referToBehaviorParams` converts to the expression "`self.<name>`" (FlexBE
// behaviors read their parameters as attributes); any other converts to its value.
// A string the script forced with `!str` stays a plain string for templates, and the converter
// remembers it: `isForcedString` answers for that very string object (templates pass values by
// reference), which targets expose as a test so that their templates always quote it.
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "backends/tmpl/values/value.h"
#include "ir/state.h"
#include "ir/value.h"

namespace smachac::generator {

class ValueConverter {
 public:
  tmpl::Value convert(const ir::Value& value);
  /// A list of the names' texts.
  tmpl::Value names(const std::vector<ir::Name>& names);
  /// Whether `value` is a string that came from a `!str`-tagged scalar.
  bool isForcedString(const tmpl::Value& value) const;
  /// From now on, values marked with one of these behavior parameter references (→ name)
  /// convert to `self.<name>`; replaces the previous set.
  void referToBehaviorParams(std::unordered_map<uint32_t, std::string> refs);

 private:
  std::unordered_map<uint32_t, std::string> param_refs_;
  std::vector<tmpl::Value> forced_;  // keeps the objects alive, so their addresses stay unique
  std::unordered_set<const void*> forced_ids_;
};

/// The backtick form of an expression: "`code`".
std::string backtickForm(std::string_view code);

}  // namespace smachac::generator
