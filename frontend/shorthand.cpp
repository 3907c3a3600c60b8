// Shorthand key expansion.
#include "frontend/shorthand.h"

#include <algorithm>
#include <array>
#include <utility>

namespace smachac::frontend {
namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 16> kShorthands = {{
    {"n", "name"},
    {"m", "manifest"},
    {"nn", "node_name"},
    {"T", "template"},
    {"S", "script"},
    {"o", "outcomes"},
    {"s", "states"},
    {"p", "params"},
    {"ud", "userdata"},
    {"ik", "input_keys"},
    {"ok", "output_keys"},
    {"r", "remapping"},
    {"t", "transitions"},
    {"do", "default_outcome"},
    {"om", "outcome_map"},
    {"cb", "callbacks"},
}};

}  // namespace

std::optional<std::string_view> longhandOf(std::string_view key) {
  for (const auto& [short_form, long_form] : kShorthands) {
    if (key == short_form) return long_form;
  }
  return std::nullopt;
}

void expandShorthand(ir::Value& mapping, DiagnosticEmitter& diags) {
  if (!mapping.isMap()) return;
  ir::Map& entries = mapping.asMap();
  bool any = std::any_of(entries.begin(), entries.end(),
                         [](const ir::MapEntry& e) { return longhandOf(e.key).has_value(); });
  if (!any) return;
  ir::Map result;
  result.reserve(entries.size());
  for (ir::MapEntry& entry : entries) {
    std::optional<std::string_view> longhand = longhandOf(entry.key);
    if (longhand && mapping.find(*longhand)) {
      diags.emit<DiagKind::ShorthandConflict>(entry.key_loc, entry.key, *longhand);
      continue;
    }
    if (longhand) entry.key = std::string(*longhand);
    result.push_back(std::move(entry));
  }
  entries = std::move(result);
}

}  // namespace smachac::frontend
