// Building template values from JSON and YAML documents (render contexts). Both keep the order
// of mapping keys, as Jinja2's dicts do. YAML uses the YAML 1.2 core schema: `yes`/`no` stay
// strings, quoted scalars are strings.
#pragma once

#include <string_view>

#include "backends/tmpl/values/value.h"

namespace YAML {  // NOLINT(readability-identifier-naming): yaml-cpp's namespace
class Node;
}

namespace smachac::tmpl {

/// Parses JSON text; raises TemplateError naming `origin` with line and column.
Value parseJson(std::string_view text, std::string_view origin);
/// Parses YAML text (one document); raises TemplateError naming `origin`.
Value parseYaml(std::string_view text, std::string_view origin);
/// Converts a yaml-cpp node; raises Fault for duplicate keys or nesting deeper than 200.
Value valueFromYaml(const YAML::Node& node);

}  // namespace smachac::tmpl
