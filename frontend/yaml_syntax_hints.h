// What a YAML syntax error of yaml-cpp probably means in a script, as a note for the user:
// yaml-cpp's messages ("end of map not found", "illegal map value") name the parser's state,
// not the mistake, which is nearly always the indentation of the line or a missing `- `.
#pragma once

#include <optional>
#include <string_view>

#include "ir/support/diagnostic_arg_types.h"

namespace smachac::frontend {

/// The hint for yaml-cpp's `message` (its text: diagnostic_arg_types.h), or nullopt when there
/// is none.
std::optional<YamlSyntaxHint> yamlSyntaxHint(std::string_view message);

}  // namespace smachac::frontend
