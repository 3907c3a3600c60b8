// Runs the simple YAML reader and yaml-cpp over the same text and prints both trees with
// every location, for the differential test and fuzzer of the simple reader.
#pragma once

#include <fmt/core.h>

#include <optional>
#include <string>
#include <string_view>

#include "frontend/simple_yaml_reader.h"
#include "frontend/yaml_events.h"
#include "ir/value_text.h"

namespace smachac::test {

inline std::string locText(const SourceLoc& loc) {
  return fmt::format("{}:{}+{}", loc.line, loc.column, loc.length);
}

/// One line per value and key: indentation, location, kind and the scalar's text.
inline void dumpYamlTree(const ir::Value& v, int depth, std::string& out) {
  std::string indent(depth * 2, ' ');
  out += fmt::format("{}{} {}", indent, locText(v.loc), ir::valueKindName(v.kind()));
  if (v.forced_string) out += " forced";
  if (v.isList()) {
    out += '\n';
    for (const ir::Value& item : v.asList()) dumpYamlTree(item, depth + 1, out);
  } else if (v.isMap()) {
    out += '\n';
    for (const ir::MapEntry& e : v.asMap()) {
      out += fmt::format("{}  key {} \"{}\"\n", indent, locText(e.key_loc), e.key);
      dumpYamlTree(e.value, depth + 2, out);
    }
  } else {
    out += " " + ir::formatValue(v) + "\n";
  }
}

struct YamlReaderComparison {
  bool simple_read = false;      ///< the simple reader did not give up
  bool reference_clean = false;  ///< yaml-cpp returned a tree and no diagnostic
  std::string simple;            ///< the trees, dumped
  std::string reference;
};

inline YamlReaderComparison compareYamlReaders(std::string_view text) {
  constexpr uint32_t kFile = 1;
  YamlReaderComparison result;
  if (std::optional<ir::Value> v = frontend::readSimpleYaml(kFile, text)) {
    result.simple_read = true;
    dumpYamlTree(*v, 0, result.simple);
  }
  DiagnosticEmitter diags;
  std::optional<ir::Value> v = frontend::buildYamlValueWithYamlCpp(kFile, text, diags);
  result.reference_clean = v && diags.diagnostics().empty();
  if (v) dumpYamlTree(*v, 0, result.reference);
  return result;
}

}  // namespace smachac::test
