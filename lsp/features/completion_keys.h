// Key completion: the keys of a state (its template's variables and SMACHA's core keys) and of
// the script's root, each with a short description, each one only while it is not written.
// A state with neither `template` nor `script` is offered those two first (a state with one
// of them is not offered the other); then its template's required variables (and choices among
// variables), its optional ones, then the core keys. The generator's own variables (`name`,
// `class_name`, `uuid`, `sm_name`, `autonomy`) are not offered.
#pragma once

#include <optional>
#include <vector>

#include "lsp/features/completion_candidates.h"

namespace smachac::lsp {

std::vector<Candidate> stateKeyCandidates(const ScopeState& state,
                                          const std::optional<TemplateInfo>& info);

/// `info`: the script's base template, whose variables describe the root keys it reads.
std::vector<Candidate> rootKeyCandidates(const ScopeState& root,
                                         const std::optional<TemplateInfo>& info);

}  // namespace smachac::lsp
