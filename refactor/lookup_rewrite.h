// Renaming params in lookups, where the frontend resolves them (frontend/lookups.h): the
// values of a state's keys other than `states`, and the immediate values of mapping-valued
// keys, when they are `[params, x]` or `[[x]]` or string constructs with such parts. Rules:
//   * a state's renames apply to its own lookups and to the states it contains, except below
//     a state that has its own param of that name (own params win over inherited ones)
//   * only the param name's scalar is replaced; the lookup keeps its style
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/value.h"
#include "refactor/text_edits.h"

namespace smachac::refactor {

using Renames = std::map<std::string, std::string, std::less<>>;

void renameParamLookups(const SourceText& text, EditList& edits, const ir::Value& body,
                        const Renames& renames);

/// The keys among `keys` that the state `body` uses by inheritance: in its lookups or those
/// of the states it contains, or by including a sub-script (whose lookups are unknown here).
std::vector<std::string> usedParams(const ir::Value& body, const std::vector<std::string>& keys);

/// The name of a sub-script that param `key` of the state `body` reaches by inheritance
/// (the state's own when it includes one), or nullopt.
std::optional<std::string> subScriptInheriting(const ir::Value& body, std::string_view key);

}  // namespace smachac::refactor
