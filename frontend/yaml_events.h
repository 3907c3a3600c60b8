// Builds an ir::Value tree straight from yaml-cpp's parse events (no yaml-cpp node graph, which
// costs most of the time and memory on large scripts). Keeps a location on every value and key,
// and reports as located diagnostics: non-scalar and duplicate keys, integer overflow, aliases
// of unfinished anchors, nesting deeper than kMaxYamlDepth and documents that expand (through
// aliases) to more than kMaxYamlNodes values.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "ir/support/diagnostic_emitter.h"
#include "ir/value.h"

namespace smachac::frontend {

inline constexpr size_t kMaxYamlDepth = 1000;  ///< yaml-cpp itself stops at 2000
inline constexpr size_t kMaxYamlNodes = 4'000'000;

/// Parses the first YAML document of `text` (file id `file`). nullopt after an error that
/// leaves no usable document; other errors are reported and the document is still returned.
std::optional<ir::Value> buildYamlValue(uint32_t file, std::string_view text,
                                        DiagnosticEmitter& diags);

}  // namespace smachac::frontend
