// The pass table and the pipeline. The order of the table is the order passes run in; every
// ordering constraint is commented next to the entries it concerns.
#include "passes/pipeline.h"

#include "ir/support/check.h"
#include "ir/verify.h"

namespace smachac::passes {
namespace {

constexpr PassInfo kPasses[] = {
    // Filled in as checks and transforms are written (one file each under validate/,
    // optimize/, analysis/).
    {"verify-ir", "check the IR's structural invariants (a failure is a compiler bug)",
     PassKind::Check,
     [](const ir::Module& m, PassContext&) {
       std::optional<std::string> problem = ir::verify(m);
       SMACHAC_CHECK(!problem, problem ? problem->c_str() : "");
     },
     nullptr},
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
  for (const PassInfo& pass : kPasses) {
    if (options.disabled.contains(pass.name)) continue;
    if (pass.kind == PassKind::Check) {
      pass.check(module, context);
    } else if (!context.diags.hasErrors()) {
      pass.transform(module, context);
      std::optional<std::string> problem = ir::verify(module);
      SMACHAC_CHECK(!problem, "a transform broke the IR");
    }
    bool print = options.print_ir_after == "all" || options.print_ir_after == pass.name;
    if (print && options.print_ir) options.print_ir(pass.name, module);
  }
  return !context.diags.hasErrors();
}

}  // namespace smachac::passes
