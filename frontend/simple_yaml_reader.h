// A fast reader for the block-style YAML SMACHA scripts are written in. It reads a document
// whose root is a block mapping or sequence at column 0, made of block mappings and sequences
// (including sequences at their key's column), one-line plain, single- and double-quoted scalars,
// flow sequences and mappings of those (over several lines when each line break follows an
// opening bracket or a comma), comments and a leading `---`. It feeds the
// events yaml-cpp would produce, with the same marks, to a YamlValueBuilder.
//
// It gives up (nullopt) on anything else, and on anything that would need a diagnostic:
// anchors, aliases, tags, block scalars, multi-line scalars, other line breaks in flow
// collections, comments in them, explicit and
// complex keys, empty sequence items, tabs, carriage returns, byte order marks, directives,
// further documents, syntax errors, duplicate keys, integer overflow, deep nesting. The
// caller then parses the text with yaml-cpp, so behaviour and diagnostics never depend on it.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "frontend/yaml_value_builder.h"
#include "ir/value.h"

namespace smachac::frontend {

/// `sink`, when given, takes the items of the root's `states` list as they are read
/// (YamlValueBuilder::setStatesSink); the tree returned then lacks the items it took.
std::optional<ir::Value> readSimpleYaml(uint32_t file, std::string_view text,
                                        StatesSink* sink = nullptr);

}  // namespace smachac::frontend
