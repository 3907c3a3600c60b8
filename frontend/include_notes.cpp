// "included from here" notes and de-duplication of a sub-script's diagnostics.
#include "frontend/include_notes.h"

#include <set>
#include <tuple>

namespace smachac::frontend {
namespace {

bool sameLoc(const SourceLoc& a, const SourceLoc& b) {
  return a.file == b.file && a.line == b.line && a.column == b.column;
}

/// The places that include `file`, each once.
std::vector<SourceLoc> distinctSites(const std::vector<SourceLoc>& sites) {
  std::vector<SourceLoc> distinct;
  for (const SourceLoc& site : sites) {
    bool seen = false;
    for (const SourceLoc& d : distinct) seen = seen || sameLoc(d, site);
    if (!seen) distinct.push_back(site);
  }
  return distinct;
}

}  // namespace

void noteInclusions(DiagnosticEmitter& diags, size_t first, const IncludeSites& sites) {
  const std::vector<Diagnostic>& all = diags.diagnostics();
  if (first >= all.size()) return;
  std::vector<Diagnostic> kept;
  std::set<std::tuple<DiagKind, uint32_t, uint32_t, uint32_t>> seen;
  for (size_t i = first; i < all.size(); ++i) {
    Diagnostic d = all[i];
    auto it = sites.find(d.loc.file);
    if (d.loc.hasFile() && it != sites.end()) {
      if (!seen.emplace(d.kind, d.loc.file, d.loc.line, d.loc.column).second) continue;
      for (const SourceLoc& site : distinctSites(it->second)) {
        d.notes.push_back(makeNote<DiagNoteKind::IncludedFromHere>(site));
      }
    }
    kept.push_back(std::move(d));
  }
  diags.replaceFrom(first, std::move(kept));
}

}  // namespace smachac::frontend
