// Finding and reading sub-scripts (`script: NAME`). NAME is searched, in order, in the
// directory of the file that includes it, then in each -S directory; in each directory as
// NAME, then NAME.yml. An absolute NAME is tried as is. Files are read once and cached; each
// inclusion gets a fresh copy of the parsed state, so one sub-script can be included several
// times with different params.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frontend/document_overlay.h"
#include "frontend/include_notes.h"
#include "frontend/yaml_loader.h"
#include "ir/state.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"
#include "ir/value.h"

namespace smachac::frontend {

/// The one state a sub-script holds: its key (ignored: the caller names it) and its body.
struct SubScriptState {
  uint32_t file = 0;
  std::string canonical_path;  ///< for include-cycle detection
  ir::MapEntry entry;
};

class SubScriptLoader {
 public:
  /// `overlay` (may be null): texts that stand for files, by canonical path.
  SubScriptLoader(std::vector<std::string> search_dirs, const DocumentOverlay* overlay,
                  SourceManager& sources, DiagnosticEmitter& diags)
      : search_dirs_(std::move(search_dirs)), overlay_(overlay), sources_(sources), diags_(diags) {}

  /// Loads the sub-script named by `script` (its location says which file includes it).
  /// Reports not-found (with the paths tried), parse errors and a wrong shape.
  std::optional<SubScriptState> load(const ir::Name& script);

  /// Files read so far, in order.
  const std::vector<uint32_t>& files() const { return files_; }
  /// Where each file read so far is included, in order.
  const IncludeSites& includeSites() const { return sites_; }

 private:
  std::vector<std::string> candidates(const ir::Name& script) const;
  /// The overlay's text for `canonical`, or null.
  const std::string* overlaid(const std::string& canonical) const;
  LoadedYaml read(const std::string& path, const std::string& canonical, SourceLoc from);
  std::optional<SubScriptState> validate(uint32_t file, const ir::Value& root);

  std::vector<std::string> search_dirs_;
  const DocumentOverlay* overlay_;
  SourceManager& sources_;
  DiagnosticEmitter& diags_;
  struct Cached {
    uint32_t file = 0;
    std::optional<ir::Value> root;
  };
  std::map<std::string, Cached> cache_;  ///< by canonical path
  std::vector<uint32_t> files_;
  IncludeSites sites_;
};

}  // namespace smachac::frontend
