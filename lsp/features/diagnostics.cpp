// Diagnostics in the protocol's shape.
#include "lsp/features/diagnostics.h"

#include <fmt/core.h>

namespace smachac::lsp {
namespace {

int severityCode(Severity severity) {
  switch (severity) {
    case Severity::Error:
      return 1;
    case Severity::Warning:
      return 2;
    case Severity::Note:
    case Severity::Ignored:
      return 3;
  }
  return 3;
}

Json locationJson(const Analysis& analysis, const SourceLoc& loc) {
  LineIndex lines(analysis.sources.content(loc.file));
  return {{"uri", analysis.uriOf(loc.file)}, {"range", toJson(lines.rangeOf(loc))}};
}

/// Where a diagnostic is shown in the document: its own location, or the first place that
/// includes its file (following inclusions up to the document).
SourceLoc shownAt(const Analysis& analysis, SourceLoc loc) {
  for (int depth = 0; loc.file != analysis.file && depth < 64; ++depth) {
    auto it = analysis.include_sites.find(loc.file);
    if (it == analysis.include_sites.end() || it->second.empty()) return {analysis.file, 0, 0, 1};
    loc = it->second.front();
  }
  return loc;
}

Json diagnosticJson(const Analysis& analysis, const Diagnostic& diagnostic) {
  SourceLoc at = diagnostic.loc.hasFile() ? shownAt(analysis, diagnostic.loc)
                                          : SourceLoc{analysis.file, 0, 0, 1};
  std::string message = diagnostic.message;
  Json related = Json::array();
  if (diagnostic.loc.hasFile() && diagnostic.loc.file != analysis.file) {
    message = fmt::format("in {}: {}", analysis.sources.path(diagnostic.loc.file), message);
    related.push_back(
        {{"location", locationJson(analysis, diagnostic.loc)}, {"message", diagnostic.message}});
  }
  for (const DiagNote& note : diagnostic.notes) {
    if (!note.loc.hasFile()) {
      message += fmt::format("\nnote: {}", note.message);
      continue;
    }
    related.push_back({{"location", locationJson(analysis, note.loc)}, {"message", note.message}});
  }
  Json json = {{"range", toJson(analysis.lines().rangeOf(at))},
               {"severity", severityCode(diagnostic.severity)},
               {"code", diagKindInfo(diagnostic.kind).name},
               {"source", "smachac"},
               {"message", message}};
  if (!related.empty()) json["relatedInformation"] = std::move(related);
  return json;
}

}  // namespace

Json publishDiagnosticsParams(const Analysis& analysis) {
  Json diagnostics = Json::array();
  for (const Diagnostic& diagnostic : analysis.diagnostics) {
    diagnostics.push_back(diagnosticJson(analysis, diagnostic));
  }
  return {{"uri", analysis.uri}, {"version", analysis.version}, {"diagnostics", diagnostics}};
}

}  // namespace smachac::lsp
