// The whole check of one script, as `smachac lint` and a compile run it: lowering (with its
// sub-scripts), the pass pipeline, the lowering of portable expressions for the target, the
// template checks and the target-code checks. Every problem goes to the emitter; a
// sub-script's diagnostics get their "included from here" notes.
#pragma once

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/document_overlay.h"
#include "frontend/include_notes.h"
#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"

namespace smachac::checker {

struct CheckOptions {
  std::string target = "smach";
  std::vector<std::string> template_dirs;  ///< -I
  std::vector<std::string> script_dirs;    ///< -S
  std::set<std::string, std::less<>> disabled_passes;
  std::string print_ir_after;  ///< a pass name, `all` or empty
  std::function<void(std::string_view pass, const ir::Module&)> print_ir;
  bool optimize = false;
  bool sub_script_alone = false;  ///< lint: a sub-script is checked in a stand-in
  const frontend::DocumentOverlay* overlay = nullptr;
  /// Keep the module lowering made even when the script has errors (an editor's navigation).
  bool keep_module_on_error = false;
};

struct CheckedScript {
  /// The checked module; with keep_module_on_error, whatever lowering made of a script with
  /// errors (then `ok` is false).
  std::optional<ir::Module> module;
  bool ok = false;
  /// Where each sub-script the script read is included.
  frontend::IncludeSites include_sites;
};

/// Checks the script `path` (read from disk, or `text` when given).
CheckedScript checkScript(const std::string& path, std::optional<std::string> text,
                          const CheckOptions& options, SourceManager& sources,
                          DiagnosticEmitter& diags);

}  // namespace smachac::checker
