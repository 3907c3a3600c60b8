// contain: the selected leaves' `userdata` moves to the script's root (SMACHA's userdata
// lift), so that the other root states still see it. Rules:
//   * an entry without lookups of a selected leaf moves (entries with lookups stay: they
//     need the state's params); for a key set by several selected leaves the last one wins,
//     as it did when they all set it at the root
//   * a key the root already sets (its `userdata` or another root leaf's) to the same value
//     is shared; to another value, it moves as `<key>_<n>` and the container remaps it
//     (lifted-userdata-renamed: the script gave the key two values before)
//   * new root entries go to the root `userdata` (created after `outcomes`, else before
//     `states`, in flow style); the state's `userdata` key goes when all its entries moved
//   * containers keep their own userdata: it is in their own scope already
#pragma once

#include <string>
#include <vector>

#include "refactor/contain_scope.h"
#include "refactor/lookup_rewrite.h"

namespace smachac::refactor {

struct UserdataPlan {
  Renames renamed;                          ///< container key -> root key
  std::vector<std::string> added;           ///< root keys the lift adds
  std::vector<std::string> inner_literals;  ///< keys set inside the container (entries that stay)
};

UserdataPlan liftUserdata(const ContainScope& scope);

}  // namespace smachac::refactor
