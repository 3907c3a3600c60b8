// The compiler's version, shown by --version and in SARIF output.
#pragma once

#include <string_view>

namespace smachac {

inline constexpr std::string_view kVersion = "0.1.0";

}  // namespace smachac
