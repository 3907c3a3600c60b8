// Formats a double exactly as Python's repr() does: the shortest text that reads back to the
// same double, with ".0" on integral values, exponent form outside [1e-4, 1e16), and
// `inf`/`-inf`/`nan`. SMACHA scripts print YAML floats this way (ruamel + Python).
#pragma once

#include <string>

namespace smachac {

std::string pythonFloatRepr(double value);

}  // namespace smachac
