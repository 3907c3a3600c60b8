// SMACHA's 16 key shorthands (n m nn T S o s p ud ik ok r t do om cb). Unlike SMACHA they are
// expanded only for the keys of the script root and of states — never inside values, so an
// outcome called `ok` or a userdata key `t` keeps its name.
#pragma once

#include <optional>
#include <string_view>

#include "ir/support/diagnostic_emitter.h"
#include "ir/value.h"

namespace smachac::frontend {

/// The longhand of a shorthand key, or nullopt.
std::optional<std::string_view> longhandOf(std::string_view key);

/// Renames shorthand keys of a mapping in place (order kept). Both `t` and `transitions`
/// present is a shorthand-conflict error; the longhand entry is kept.
void expandShorthand(ir::Value& mapping, DiagnosticEmitter& diags);

}  // namespace smachac::frontend
