// The target table.
#include "backends/targets.h"

#include "backends/cpp/cpp_target.h"
#include "backends/dot/dot_target.h"
#include "backends/flexbe/flexbe_target.h"
#include "backends/smach/smach_target.h"
#include "ir/json.h"
#include "ir/printer.h"

namespace smachac::backends {
namespace {

std::optional<std::vector<OutputFile>> emitIrText(ir::Module&& m, EmitContext& ctx) {
  return std::vector<OutputFile>{{"", ir::printModule(m, ctx.sources)}};
}

std::optional<std::vector<OutputFile>> emitIrJson(ir::Module&& m, EmitContext& ctx) {
  return std::vector<OutputFile>{{"", ir::moduleToJson(m, ctx.sources)}};
}

constexpr Target kTargets[] = {
    {"ir", "the IR in its stable text form", &emitIrText},
    {"json", "the IR as JSON (format smachac-ir, version 1)", &emitIrJson},
    {"smach", "SMACH Python, rendered from SMACHA-compatible templates", &smach::emitSmach},
    {"dot", "the state graph for Graphviz (clusters, outcome-labelled edges)", &dot::emitDot},
    {"flexbe", "a FlexBE behavior: <name>_sm.py, its states and manifest (-o DIR)",
     &flexbe::emitFlexbe},
    {"cpp", "C++20 for the smachac runtime: one translation unit with main()", &cpp::emitCpp},
};

}  // namespace

std::span<const Target> targets() { return kTargets; }

std::vector<std::string> optionalBlocksSkipped(const EmitOptions& options) {
  std::vector<std::string> skip;
  if (!options.comments) skip.insert(skip.end(), {"upper_comments", "lower_comments"});
  if (!options.introspection) skip.insert(skip.end(), {"introspection_server", "spin"});
  return skip;
}

const Target* findTarget(std::string_view name) {
  for (const Target& t : kTargets) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

}  // namespace smachac::backends
