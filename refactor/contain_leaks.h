// contain: SMACHA's params leak: a root state that includes a
// sub-script hands its params to every later root state. Once that state is inside the
// container, its params leak only inside it. Rules:
//   * a root state after the selection whose last preceding root include is selected, and
//     that uses (by a lookup, or through a sub-script it includes) a param it does not set
//     itself, gets that param written into its own `params`, with the value it had, so it
//     keeps resolving the same (own params win over any later leak)
//   * other leaks are unchanged: the container still receives the leaks of earlier includes
#pragma once

#include "refactor/contain_scope.h"

namespace smachac::refactor {

void keepLeakedParams(const ContainScope& scope);

}  // namespace smachac::refactor
