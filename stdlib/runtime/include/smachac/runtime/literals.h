// Literal forms of a state's declarations, as hand-written code can write them for a state:
//
//   sm.add("INC", std::make_unique<rt::CallbacksState>(rt::SpecLiteral{.input_keys = {"n"}}, ...),
//          {{"succeeded", "CHECK"}}, {{"n", "counter"}});
//
// and their C-string forms, which generated code writes (StateMachine::emplace):
//
//   sm.emplace<rt::CallbacksState>("INC", {{"succeeded", "CHECK"}}, {{"n", "counter"}},
//                                  rt::CStringSpec{.input_keys = {"n"}}, ...);
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
struct StateMachineSpec;

/// The text of a C string of the C-string forms below; a null one (from hand-written code)
/// reads as "", not as undefined behaviour.
inline std::string_view cStringText(const char* text) { return text != nullptr ? text : ""; }

/// One entry of a map of strings: a transition (outcome, target) or a remapping (state key,
/// parent key).
struct PairLiteral {
  std::string_view first;
  std::string_view second;
};
using PairsLiteral = std::initializer_list<PairLiteral>;

/// The same with C strings, which are what generated code passes to emplace (state_machine.h):
/// a pair of string literals is two addresses, where a PairLiteral's views cost a call each
/// at -O0 (about a third of a millisecond of compile time per transition).
struct CStringPair {
  const char* first;
  const char* second;
};
using CStringPairs = std::initializer_list<CStringPair>;

/// The map `pairs` write; the first of equal keys wins, as in a std::map's initializer list.
std::map<std::string, std::string, std::less<>> toMap(PairsLiteral pairs);
/// toMap() of C strings (not an overload: `toMap({})` would be ambiguous).
std::map<std::string, std::string, std::less<>> cStringMap(CStringPairs pairs);

/// StateSpec's literal form; converts to StateSpec (outcomes, input and output keys in order).
struct SpecLiteral {
  std::initializer_list<std::string_view> outcomes{};
  std::initializer_list<std::string_view> input_keys{};
  std::initializer_list<std::string_view> output_keys{};

  /// Implicit, so that a state class taking a StateSpec can be given a SpecLiteral.
  operator StateSpec() const;
};

/// The same with C strings, what generated code writes (`rt::CStringSpec{.outcomes = {"a"}}`):
/// its keys cost the call nothing, a SpecLiteral's views a call each at -O0.
struct CStringSpec {
  std::initializer_list<const char*> outcomes{};
  std::initializer_list<const char*> input_keys{};
  std::initializer_list<const char*> output_keys{};

  operator StateSpec() const;
  /// So that generated code gives a StateMachine its spec in this form too.
  operator StateMachineSpec() const;
};

}  // namespace smachac::runtime
