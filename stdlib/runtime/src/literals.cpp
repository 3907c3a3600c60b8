// The owning forms of the literals generated code writes (literals.h).
#include "smachac/runtime/literals.h"

#include <utility>

#include "smachac/runtime/state.h"
#include "smachac/runtime/state_machine.h"

namespace smachac::runtime {

namespace {

std::string_view textOf(std::string_view text) { return text; }
std::string_view textOf(const char* text) { return cStringText(text); }

template <class Key>
Keys keysOf(std::initializer_list<Key> literal) {
  Keys keys;
  keys.reserve(literal.size());
  for (const Key& key : literal) keys.emplace_back(textOf(key));
  return keys;
}

template <class Pairs>
std::map<std::string, std::string, std::less<>> mapOf(Pairs pairs) {
  std::map<std::string, std::string, std::less<>> map;
  for (const auto& pair : pairs) map.emplace(textOf(pair.first), textOf(pair.second));
  return map;
}

template <class Spec>
StateSpec specOf(const Spec& spec) {
  return StateSpec{.outcomes = keysOf(spec.outcomes),
                   .input_keys = keysOf(spec.input_keys),
                   .output_keys = keysOf(spec.output_keys)};
}

}  // namespace

std::map<std::string, std::string, std::less<>> toMap(PairsLiteral pairs) { return mapOf(pairs); }

std::map<std::string, std::string, std::less<>> cStringMap(CStringPairs pairs) {
  return mapOf(pairs);
}

SpecLiteral::operator StateSpec() const { return specOf(*this); }

CStringSpec::operator StateSpec() const { return specOf(*this); }

CStringSpec::operator StateMachineSpec() const {
  StateSpec keys = specOf(*this);
  return StateMachineSpec{.outcomes = std::move(keys.outcomes),
                          .input_keys = std::move(keys.input_keys),
                          .output_keys = std::move(keys.output_keys)};
}

}  // namespace smachac::runtime
