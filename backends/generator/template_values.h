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

#include <array>
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
  /// A name's text as a template string. The strings of recent names are shared (strings are
  /// immutable in templates): a state's outcomes, keys and targets mostly repeat its
  /// neighbours', and each new string is an allocation a state's render would later free.
  tmpl::Value text(const ir::Symbol& name) { return cachedText(&name.str(), name); }
  /// A string literal as a template string, shared in the same way (a state's variable names).
  template <size_t N>
  tmpl::Value literal(const char (&text)[N]) {
    return cachedText(text, std::string_view(text, N - 1));
  }
  /// Whether `value` is a string that came from a `!str`-tagged scalar.
  bool isForcedString(const tmpl::Value& value) const;
  /// From now on, values marked with one of these behavior parameter references (→ name)
  /// convert to `self.<name>`; replaces the previous set.
  void referToBehaviorParams(std::unordered_map<uint32_t, std::string> refs);

 private:
  /// The shared string of `text`, whose address `identity` is stable and names that text.
  tmpl::Value cachedText(const void* identity, std::string_view text);

  /// A direct-mapped cache of strings, keyed by the address of an interned text or a literal.
  struct CachedText {
    const void* key = nullptr;
    tmpl::Value value;
  };
  static constexpr size_t kTextCacheSize = 64;

  std::unordered_map<uint32_t, std::string> param_refs_;
  std::array<CachedText, kTextCacheSize> texts_;
  std::vector<tmpl::Value> forced_;  // keeps the objects alive, so their addresses stay unique
  std::unordered_set<const void*> forced_ids_;
};

/// The backtick form of an expression: "`code`".
std::string backtickForm(std::string_view code);

}  // namespace smachac::generator
