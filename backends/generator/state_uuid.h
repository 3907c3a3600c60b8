// Deterministic ids for states, shaped like SMACHA's uuid4().hex: 32 lowercase hex digits with
// version nibble 4 and variant nibble 8–b, so that SMACHA's test normaliser recognises them.
// They are derived from a hash of the script's file name (without its directory: output must
// not depend on where the compiler runs) and the state's path, so output is reproducible.
#pragma once

#include <string>
#include <string_view>

namespace smachac::generator {

/// The id of the state at `state_path` ("ROOT/SUB/FOO") of the script file `script_path`.
std::string stateUuid(std::string_view script_path, std::string_view state_path);

}  // namespace smachac::generator
