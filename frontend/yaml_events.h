// YAML text → ir::Value tree with a location on every value and key (the builder in
// yaml_value_builder.h reports the problems). The simple reader (simple_yaml_reader.h) reads
// the block-style YAML that SMACHA scripts are written in, several times faster than
// yaml-cpp; any text it is not certain about is parsed by yaml-cpp instead, which yields the
// same tree and every diagnostic.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "frontend/yaml_value_builder.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/value.h"

namespace smachac::frontend {

/// Parses the one YAML document of `text` (file id `file`). nullopt after an error that
/// leaves no usable document, a second document included; other errors are reported and the
/// document is still returned.
std::optional<ir::Value> buildYamlValue(uint32_t file, std::string_view text,
                                        DiagnosticEmitter& diags);

/// The same through yaml-cpp only (the reference the simple reader is tested against).
std::optional<ir::Value> buildYamlValueWithYamlCpp(uint32_t file, std::string_view text,
                                                   DiagnosticEmitter& diags);

}  // namespace smachac::frontend
