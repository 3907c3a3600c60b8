// StateKind names from state_kind.def.
#include "ir/state_kind.h"

namespace smachac::ir {

std::string_view stateKindName(StateKind kind) {
  switch (kind) {
#define SMACHAC_STATE_KIND(name, text) \
  case StateKind::name:                \
    return text;
#include "ir/state_kind.def"
  }
  return "leaf";
}

}  // namespace smachac::ir
