// The pass table and the pipeline. The order of the table is the order passes run in; every
// ordering constraint is commented next to the entries it concerns.
#include "passes/pipeline.h"

#include "ir/support/check.h"
#include "ir/verify.h"
#include "passes/analysis/userdata_scope.h"
#include "passes/optimize/transforms.h"
#include "passes/validate/checks.h"

namespace smachac::passes {
namespace {

void verifyIr(const ir::Module& module, PassContext&) {
  std::optional<std::string> problem = ir::verify(module);
  SMACHAC_CHECK(!problem, problem ? problem->c_str() : "");
}

constexpr PassInfo check(std::string_view name, std::string_view description, CheckFn fn) {
  return {name, description, PassKind::Check, fn, nullptr};
}

constexpr PassInfo transform(std::string_view name, std::string_view description, TransformFn fn) {
  return {name, description, PassKind::Transform, nullptr, fn};
}

constexpr PassInfo kPasses[] = {
    // The frontend's output must be well formed before any check walks it.
    check("verify-ir", "check the IR's structural invariants (a failure is a compiler bug)",
          verifyIr),

    // Checks: read-only, all of them run even after errors. They depend only on the
    // frontend's resolution of transitions, not on each other; the order is the order their
    // diagnostics appear in: names, then the graph, then the data flowing through it.
    check("check-names", "duplicate state names, names clashing with outcomes, identifiers",
          checkNames),
    check("check-transitions", "transition targets and the mapping of declared outcomes",
          checkTransitions),
    check("check-concurrence", "outcome maps, default outcomes and parallel writes",
          checkConcurrence),
    check("check-reachability", "unreachable states, livelocks, containers that never finish",
          checkReachability),
    check("check-userdata-flow", "userdata keys read before they are defined on every path",
          checkUserdataFlow),
    check("check-userdata-usage", "userdata values overwritten or never read", checkUserdataUsage),
    check("check-userdata-types", "literal types of keys copied across containers",
          checkUserdataTypes),
    check("check-expressions", "portable expressions (`!expr`): names, types, where they stand",
          checkExpressions),

    // Transforms: only with PipelineOptions::optimize, and only on a module without errors
    // (warnings, and errors downgraded with -Wno-error=, are fine: unresolved targets and
    // unmapped outcomes make a transform leave that part alone).
    // Pruning first: it hoists the userdata of pruned states into their container, which
    // dedupe-userdata then cleans, and it can leave containers with a single state to fold.
    transform("prune-unreachable-states", "remove states no transition path reaches",
              pruneUnreachableStates),
    transform("dedupe-userdata", "remove userdata entries that repeat the value in effect",
              dedupeUserdata),
    // Last: it folds only containers whose state sets no userdata in them, which the two
    // passes above may have removed.
    transform("fold-trivial-containers",
              "replace a StateMachine holding one pass-through state by that state",
              foldTrivialContainers),
};

}  // namespace

std::span<const PassInfo> passTable() { return kPasses; }

const PassInfo* findPass(std::string_view name) {
  for (const PassInfo& pass : kPasses) {
    if (pass.name == name) return &pass;
  }
  return nullptr;
}

bool runPipeline(ir::Module& module, PassContext& context, const PipelineOptions& options) {
  size_t errors_before = context.diags.errorCount();
  auto has_errors = [&] { return context.diags.errorCount() > errors_before; };
  for (const PassInfo& pass : kPasses) {
    if (options.disabled.contains(pass.name)) continue;
    if (pass.kind == PassKind::Check) {
      pass.check(module, context);
    } else if (options.optimize && !has_errors()) {
      if (context.userdata_scopes) context.userdata_scopes->clear();
      pass.transform(module, context);
      std::optional<std::string> problem = ir::verify(module);
      SMACHAC_CHECK(!problem, problem ? problem->c_str() : "a transform broke the IR");
    }
    bool print = options.print_ir_after == "all" || options.print_ir_after == pass.name;
    if (print && options.print_ir) options.print_ir(pass.name, module);
  }
  if (context.userdata_scopes) context.userdata_scopes->clear();
  return !has_errors();
}

}  // namespace smachac::passes
