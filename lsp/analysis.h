// One analysis of one open document: the whole check the command line's lint runs (with the
// editor's unsaved sub-scripts), kept for the features that answer requests. It owns the
// sources it read; locations in its diagnostics and module refer to them.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "frontend/include_notes.h"
#include "ir/module.h"
#include "ir/support/diagnostic.h"
#include "ir/support/source_manager.h"
#include "ir/value.h"
#include "lsp/documents.h"
#include "lsp/positions.h"
#include "lsp/settings.h"

namespace smachac::lsp {

struct Analysis {
  static constexpr int64_t kNotOpen = -1;

  std::string uri;
  int64_t version = 0;  ///< the document's; kNotOpen for a file the editor does not have open
  SourceManager sources;
  uint32_t file = 0;  ///< the document's file id in `sources`
  /// The document's YAML tree (with locations); empty when its YAML does not parse.
  std::optional<ir::Value> yaml;
  /// False for a YAML document that is not a SMACHA script: it gets no diagnostics.
  bool is_script = true;
  std::vector<Diagnostic> diagnostics;
  /// What lowering made of the script, even with errors; checked when `ok`.
  std::optional<ir::Module> module;
  bool ok = false;
  frontend::IncludeSites include_sites;
  /// Canonical paths of the other files the analysis read (its sub-scripts).
  std::set<std::string> dependencies;

  std::string_view text() const { return sources.content(file); }
  LineIndex lines() const { return LineIndex(text()); }
  /// The path or URI of a file of this analysis, as a URI.
  std::string uriOf(uint32_t file_id) const;
};

/// Checks `document` with `settings`; sub-scripts open in the editor are read from `overlay`.
std::unique_ptr<Analysis> analyze(const Document& document, const Settings& settings,
                                  const frontend::DocumentOverlay& overlay);

/// Whether a YAML tree looks like a SMACHA script or sub-script (a mapping with a script key,
/// or a list of one `NAME: {state}` mapping).
bool looksLikeScript(const ir::Value& root);

}  // namespace smachac::lsp
