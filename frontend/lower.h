// The frontend's one entry point: a SMACHA script file → ir::Module.
//
//   script ::= {name, template, states, outcomes?, userdata?, manifest?, node_name?,
//               function_name?, params?}
//   states ::= [ {NAME: state} ... ]          (nested lists are flattened)
//   state  ::= container {states, template, ...} | include {script, ...} | leaf {template, ...}
//
// Shorthands are expanded at root and state keys; params are inherited and lookups resolved
// per state in document order (as SMACHA does). The script's `params` (ignored by
// SMACHA) and those of a sub-script's state are behavior parameters: their children inherit
// them marked as such (Value::behavior_param), so that FlexBE can refer to them. Sub-scripts
// are included with the caller's overrides; transitions are resolved to siblings or container
// outcomes. Every error is reported (the walk goes on after one); the module is returned only
// when there were none. The main script's states are lowered while the rest is being read
// (FrontendOptions::stream_states): the module and diagnostics are those of reading first.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "frontend/document_overlay.h"
#include "frontend/include_notes.h"
#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"

namespace smachac::frontend {

struct FrontendOptions {
  std::vector<std::string> script_dirs;  ///< -S, searched after the including file's dir
  /// When set, filled with where each sub-script is included (include_notes.h).
  IncludeSites* include_sites = nullptr;
  /// lint: a script that is a sub-script is checked in a stand-in (standalone_sub_script.h).
  bool sub_script_alone = false;
  /// Texts that stand for files, by canonical path (an editor's unsaved documents): a
  /// sub-script found here is read from here, whether or not it exists on disk.
  const DocumentOverlay* overlay = nullptr;
  /// An editor's analysis: the module is returned even when lowering reported errors, as far
  /// as it got (states whose keys failed are kept as written or left out). It is for
  /// navigation only: the passes never see a module with frontend errors.
  bool keep_module_on_error = false;
  /// Lower the states of the root's `states` list while the rest of the script is being read
  /// (the same module and diagnostics, without the whole YAML tree in memory at once); off:
  /// read everything, then lower (the reference the streamed way is tested against).
  bool stream_states = true;
};

std::optional<ir::Module> lowerScript(const std::string& path, const FrontendOptions& options,
                                      SourceManager& sources, DiagnosticEmitter& diags);

/// The same for script text already in memory (`path` names it in diagnostics and is the
/// base for sub-script lookups). Used by fuzzers and tools that hold the text.
std::optional<ir::Module> lowerScriptText(const std::string& path, std::string text,
                                          const FrontendOptions& options, SourceManager& sources,
                                          DiagnosticEmitter& diags);

}  // namespace smachac::frontend
