// A pass: a stable kebab-case name, a one-line description, and one free function. Checks
// read the IR and report every problem they find; transforms rewrite it and say whether
// anything changed. The pass table (pipeline.cpp) is the only list of passes.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"

namespace smachac::passes {

class UserdataScopeCache;

/// What passes may look at besides the IR.
struct PassContext {
  const SourceManager& sources;
  DiagnosticEmitter& diags;
  std::string target;  ///< the output target (smach, cpp, flexbe, ir, ...): identifier rules
  /// Containers' userdata scopes, built once for the checks that share them
  /// (analysis/userdata_scope.h: `userdataScope`); runPipeline clears it when the IR changes.
  std::shared_ptr<UserdataScopeCache> userdata_scopes = nullptr;
};

using CheckFn = void (*)(const ir::Module&, PassContext&);
using TransformFn = bool (*)(ir::Module&, PassContext&);

enum class PassKind { Check, Transform };

struct PassInfo {
  std::string_view name;
  std::string_view description;
  PassKind kind;
  CheckFn check = nullptr;          ///< set for checks
  TransformFn transform = nullptr;  ///< set for transforms
};

}  // namespace smachac::passes
