// Literal forms of a state's declarations, as generated code writes them for every state:
//
//   sm.add("INC", std::make_unique<rt::CallbacksState>(rt::SpecLiteral{.input_keys = {"n"}}, ...),
//          {{"succeeded", "CHECK"}}, {{"n", "counter"}});
//
// They only point at their strings (string literals, or strings that outlive the statement),
// so they have nothing to destroy: a statement that adds a state compiles to a few calls
// without clean-up code, and a program of a thousand states compiles several times faster
// than with the owning types (StateSpec, Transitions, Remapping), which the library builds
// from them. Hand-written code can use either form.
#pragma once

#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>

namespace smachac::runtime {

struct StateSpec;

/// One entry of a map of strings: a transition (outcome, target) or a remapping (state key,
/// parent key).
struct PairLiteral {
  std::string_view first;
  std::string_view second;
};
using PairsLiteral = std::initializer_list<PairLiteral>;

/// The map `pairs` write; the first of equal keys wins, as in a std::map's initializer list.
std::map<std::string, std::string, std::less<>> toMap(PairsLiteral pairs);

/// StateSpec's literal form; converts to StateSpec (outcomes, input and output keys in order).
struct SpecLiteral {
  std::initializer_list<std::string_view> outcomes{};
  std::initializer_list<std::string_view> input_keys{};
  std::initializer_list<std::string_view> output_keys{};

  /// Implicit, so that a state class taking a StateSpec can be given a SpecLiteral.
  operator StateSpec() const;
};

}  // namespace smachac::runtime
