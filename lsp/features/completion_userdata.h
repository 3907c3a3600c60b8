// Userdata key completion. The keys in scope of a state (the last of `chain`), nearest first:
//   * its own `userdata` (a leaf's is set in its container's userdata);
//   * for a container, its states' output keys (what it can pass out);
//   * its container's userdata, input and output keys, its siblings' output keys (through
//     their remapping: the container's key each one writes) and leaf siblings' userdata;
//   * the same of the containers further out.
// `input_keys` and `output_keys` items leave out the keys the list already has.
#pragma once

#include <string_view>
#include <vector>

#include "lsp/features/completion_candidates.h"

namespace smachac::lsp {

/// `list_key`: `input_keys` or `output_keys` (whose names are left out), or "".
std::vector<Candidate> userdataCandidates(const std::vector<ScopeState>& chain,
                                          std::string_view list_key);

/// `remapping` keys: the state's input and output keys that are not remapped yet.
std::vector<Candidate> remapKeyCandidates(const ScopeState& state);

}  // namespace smachac::lsp
