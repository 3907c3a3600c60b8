// Reads a YAML file into an ir::Value tree (yaml_events.h) whose every node and mapping key carries
// its file:line:col. Checks before parsing: the path is a readable regular file, not larger than
// kMaxScriptBytes, valid UTF-8 without NUL bytes. While converting: mapping keys are scalars
// and unique, integers fit in 64 bits, nesting and total size (alias expansion) are bounded.
// Every problem is a located diagnostic; the result is empty when the file cannot be used.
#pragma once

#include <optional>
#include <string>

#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"
#include "ir/value.h"

namespace smachac::frontend {

inline constexpr size_t kMaxScriptBytes = 32u << 20;

struct LoadedYaml {
  uint32_t file = 0;
  std::optional<ir::Value> root;  ///< empty on errors
};

/// Reads `path` and registers its text in `sources`: the file id, or 0 after a diagnostic.
uint32_t readYamlFile(const std::string& path, SourceLoc from, SourceManager& sources,
                      DiagnosticEmitter& diags);

/// Reads and parses `path` (`from` is the location that asked for it, for diagnostics about
/// unreadable files; invalid for the main script).
LoadedYaml loadYamlFile(const std::string& path, SourceLoc from, SourceManager& sources,
                        DiagnosticEmitter& diags);

/// Parses text already registered in `sources` as `file`.
std::optional<ir::Value> parseYaml(uint32_t file, const SourceManager& sources,
                                   DiagnosticEmitter& diags);

}  // namespace smachac::frontend
