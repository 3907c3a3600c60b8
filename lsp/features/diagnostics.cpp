// Diagnostics in the protocol's shape.
#include "lsp/features/diagnostics.h"

#include <fmt/core.h>

#include <filesystem>

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

/// A sub-script's path as seen from the document's directory (`sub/greet.yml`).
std::string relativeName(const Analysis& analysis, uint32_t file) {
  namespace fs = std::filesystem;
  fs::path path = fs::path(analysis.sources.path(file)).lexically_normal();
  fs::path base = fs::path(analysis.sources.path(analysis.file)).parent_path();
  fs::path relative = path.lexically_relative(base.empty() ? fs::path(".") : base);
  return relative.empty() ? path.string() : relative.string();
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

}  // namespace

Json diagnosticJson(const Analysis& analysis, const Diagnostic& diagnostic) {
  SourceLoc at = diagnostic.loc.hasFile() ? shownAt(analysis, diagnostic.loc)
                                          : SourceLoc{analysis.file, 0, 0, 1};
  std::string message = diagnostic.message;
  Json related = Json::array();
  if (diagnostic.loc.hasFile() && diagnostic.loc.file != analysis.file) {
    message = fmt::format("in {}: {}", relativeName(analysis, diagnostic.loc.file), message);
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

Json publishDiagnosticsParams(const Analysis& analysis) {
  Json diagnostics = Json::array();
  for (const Diagnostic& diagnostic : analysis.diagnostics) {
    diagnostics.push_back(diagnosticJson(analysis, diagnostic));
  }
  Json params = {{"uri", analysis.uri}, {"diagnostics", diagnostics}};
  if (analysis.version != Analysis::kNotOpen) params["version"] = analysis.version;
  return params;
}

}  // namespace smachac::lsp
