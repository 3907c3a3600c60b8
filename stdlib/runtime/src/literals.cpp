// The owning forms of the literals generated code writes (literals.h).
#include "smachac/runtime/literals.h"

#include "smachac/runtime/state.h"

namespace smachac::runtime {

namespace {

Keys keysOf(std::initializer_list<std::string_view> literal) {
  return Keys(literal.begin(), literal.end());
}

}  // namespace

std::map<std::string, std::string, std::less<>> toMap(PairsLiteral pairs) {
  std::map<std::string, std::string, std::less<>> map;
  for (const PairLiteral& pair : pairs) map.emplace(pair.first, pair.second);
  return map;
}

SpecLiteral::operator StateSpec() const {
  return StateSpec{.outcomes = keysOf(outcomes),
                   .input_keys = keysOf(input_keys),
                   .output_keys = keysOf(output_keys)};
}

}  // namespace smachac::runtime
