// StateKind, from state_kind.def.
#pragma once

#include <cstdint>
#include <string_view>

namespace smachac::ir {

enum class StateKind : uint8_t {
#define SMACHAC_STATE_KIND(name, text) name,
#include "ir/state_kind.def"
};

std::string_view stateKindName(StateKind kind);

inline bool isContainer(StateKind kind) {
  return kind == StateKind::Base || kind == StateKind::StateMachine ||
         kind == StateKind::Concurrence;
}

}  // namespace smachac::ir
