// The pass pipeline: runs the pass table in order, honouring -disable-pass and
// -print-ir-after, and verifying the IR after every pass.
#pragma once

#include <functional>
#include <set>
#include <span>
#include <string>

#include "passes/pass.h"

namespace smachac::passes {

std::span<const PassInfo> passTable();
const PassInfo* findPass(std::string_view name);

struct PipelineOptions {
  std::set<std::string, std::less<>> disabled;  ///< pass names
  std::string print_ir_after;                   ///< a pass name, "all", or empty
  /// Run the transforms (the optimisation passes). Off by default: without it the module the
  /// backends see is exactly the checked script.
  bool optimize = false;
  /// Called with (pass name, module) after each pass named by print_ir_after.
  std::function<void(std::string_view, const ir::Module&)> print_ir;
};

/// Runs every enabled pass. Checks all run even after errors (so everything is reported);
/// transforms run only when `optimize` is set and while the module has no errors. Returns
/// false on errors.
bool runPipeline(ir::Module& module, PassContext& context, const PipelineOptions& options);

}  // namespace smachac::passes
