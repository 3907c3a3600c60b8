// Text, JSON and SARIF output of diagnostics.
#include "ir/support/diagnostic_printer.h"

#include <fmt/core.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "ir/support/utf8.h"
#include "ir/support/version.h"

namespace smachac {
namespace {

using Json = nlohmann::ordered_json;

std::string locationPrefix(SourceLoc loc, const SourceManager& sources) {
  if (!loc.hasFile()) return "smachac";
  const std::string& path = sources.path(loc.file);
  if (!loc.hasLine()) return path;
  return fmt::format("{}:{}:{}", path, loc.line, loc.column);
}

constexpr size_t kSnippetWidth = 120;  ///< longer lines are shown as a window around the caret

/// The line as it is shown: control characters and invalid UTF-8 bytes as '?', so that
/// diagnostics are always printable text.
std::string printable(std::string_view line) {
  std::string out;
  for (size_t i = 0; i < line.size();) {
    size_t length = utf8SequenceLength(line, i);
    unsigned char c = static_cast<unsigned char>(line[i]);
    if (length == 0 || (c < 0x20 && c != '\t') || c == 0x7f) {
      out += '?';
      i += 1;
    } else {
      out.append(line, i, length);
      i += length;
    }
  }
  return out;
}

/// Spaces (tabs kept as tabs) that move a caret under byte `bytes` of a UTF-8 line.
std::string caretPadding(std::string_view line, size_t bytes) {
  std::string pad;
  for (size_t i = 0; i < bytes && i < line.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(line[i]);
    if ((c & 0xC0) == 0x80) continue;  // continuation byte of a multi-byte character
    pad += c == '\t' ? '\t' : ' ';
  }
  return pad;
}

size_t codePoints(std::string_view text) {
  size_t count = 0;
  for (char c : text) count += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return count;
}

/// Cuts a long line to a window around byte `column`; adjusts `column` to the window.
std::string windowAround(std::string line, size_t& column) {
  if (line.size() <= kSnippetWidth) return line;
  size_t start = column > kSnippetWidth / 2 ? column - kSnippetWidth / 2 : 0;
  while (start > 0 && (static_cast<unsigned char>(line[start]) & 0xC0) == 0x80) --start;
  size_t end = std::min(line.size(), start + kSnippetWidth);
  while (end < line.size() && (static_cast<unsigned char>(line[end]) & 0xC0) == 0x80) ++end;
  std::string window =
      (start > 0 ? "..." : "") + line.substr(start, end - start) + (end < line.size() ? "..." : "");
  column = column - start + (start > 0 ? 3 : 0);
  return window;
}

/// A message on one line: the names it quotes may hold line breaks and control characters,
/// which are shown as escapes (\n, \xNN) so that no name can start a line of its own.
std::string oneLine(std::string_view message) {
  std::string out;
  for (char c : message) {
    auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (byte < 0x20 || byte == 0x7f) {
      out += fmt::format("\\x{:02x}", byte);
    } else {
      out += c;
    }
  }
  return out;
}

void appendSnippet(std::string& out, SourceLoc loc, const SourceManager& sources) {
  if (!loc.hasFile() || !loc.hasLine()) return;
  size_t column = loc.column > 0 ? loc.column - 1 : 0;
  std::string line = windowAround(printable(sources.lineText(loc.file, loc.line)), column);
  out += line;
  out += '\n';
  out += caretPadding(line, column);
  size_t rest = column < line.size() ? codePoints(std::string_view(line).substr(column)) : 1;
  size_t length = std::clamp<size_t>(loc.length, 1, std::max<size_t>(rest, 1));
  out += '^';
  out.append(length - 1, '~');
  out += '\n';
}

Json locationJson(SourceLoc loc, const SourceManager& sources) {
  Json j = Json::object();
  j["file"] = loc.hasFile() ? Json(sources.path(loc.file)) : Json(nullptr);
  j["line"] = loc.line;
  j["column"] = loc.column;
  j["length"] = loc.length;
  return j;
}

Json diagnosticJson(const Diagnostic& d, const SourceManager& sources) {
  Json j = Json::object();
  j["kind"] = diagKindInfo(d.kind).name;
  j["severity"] = severityName(d.severity);
  j["message"] = d.message;
  j.update(locationJson(d.loc, sources));
  Json notes = Json::array();
  for (const DiagNote& n : d.notes) {
    Json note = Json::object();
    note["message"] = n.message;
    note.update(locationJson(n.loc, sources));
    notes.push_back(std::move(note));
  }
  j["notes"] = std::move(notes);
  return j;
}

Json sarifLocation(SourceLoc loc, const SourceManager& sources) {
  Json physical = Json::object();
  physical["artifactLocation"] = {{"uri", sources.path(loc.file)}};
  if (loc.hasLine()) {
    physical["region"] = {{"startLine", loc.line},
                          {"startColumn", loc.column},
                          {"endColumn", loc.column + std::max<uint32_t>(loc.length, 1)}};
  }
  return Json{{"physicalLocation", physical}};
}

Json sarifResult(const Diagnostic& d, const SourceManager& sources) {
  Json result = Json::object();
  result["ruleId"] = diagKindInfo(d.kind).name;
  result["level"] = d.severity == Severity::Error ? "error" : "warning";
  result["message"] = {{"text", d.message}};
  Json locations = Json::array();
  if (d.loc.hasFile()) locations.push_back(sarifLocation(d.loc, sources));
  result["locations"] = locations;
  Json related = Json::array();
  for (const DiagNote& n : d.notes) {
    if (!n.loc.hasFile()) continue;
    Json loc = sarifLocation(n.loc, sources);
    loc["message"] = {{"text", n.message}};
    related.push_back(std::move(loc));
  }
  if (!related.empty()) result["relatedLocations"] = related;
  return result;
}

Json sarifLog(std::span<const Diagnostic> diagnostics, const SourceManager& sources) {
  Json rules = Json::array();
  std::vector<DiagKind> used;
  for (const Diagnostic& d : diagnostics) {
    if (std::find(used.begin(), used.end(), d.kind) == used.end()) used.push_back(d.kind);
  }
  for (DiagKind kind : used) {
    const DiagKindInfo& info = diagKindInfo(kind);
    Json rule = {{"id", info.name}, {"name", info.name}};
    rule["defaultConfiguration"] = {
        {"level", info.default_severity == Severity::Error ? "error" : "warning"}};
    rules.push_back(std::move(rule));
  }
  Json results = Json::array();
  for (const Diagnostic& d : diagnostics) results.push_back(sarifResult(d, sources));
  Json driver = {{"name", "smachac"}, {"version", std::string(kVersion)}, {"rules", rules}};
  Json run = {{"tool", {{"driver", driver}}}, {"results", results}};
  return {{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
          {"version", "2.1.0"},
          {"runs", Json::array({run})}};
}

}  // namespace

std::optional<DiagnosticFormat> parseDiagnosticFormat(std::string_view name) {
  if (name == "text") return DiagnosticFormat::Text;
  if (name == "json") return DiagnosticFormat::Json;
  if (name == "sarif") return DiagnosticFormat::Sarif;
  return std::nullopt;
}

std::string formatDiagnosticText(const Diagnostic& d, const SourceManager& sources) {
  std::string out =
      fmt::format("{}: {}: {} [{}]\n", locationPrefix(d.loc, sources), severityName(d.severity),
                  oneLine(d.message), diagKindInfo(d.kind).name);
  appendSnippet(out, d.loc, sources);
  for (const DiagNote& n : d.notes) {
    std::string prefix = n.loc.hasFile() ? locationPrefix(n.loc, sources) + ": " : "";
    out += fmt::format("{}note: {}\n", prefix, oneLine(n.message));
    appendSnippet(out, n.loc, sources);
  }
  return out;
}

void printDiagnostics(std::ostream& out, std::span<const Diagnostic> diagnostics,
                      const SourceManager& sources, DiagnosticFormat format) {
  switch (format) {
    case DiagnosticFormat::Text:
      for (const Diagnostic& d : diagnostics) out << formatDiagnosticText(d, sources);
      return;
    case DiagnosticFormat::Json: {
      Json all = Json::array();
      for (const Diagnostic& d : diagnostics) all.push_back(diagnosticJson(d, sources));
      out << all.dump(2) << '\n';
      return;
    }
    case DiagnosticFormat::Sarif:
      out << sarifLog(diagnostics, sources).dump(2) << '\n';
      return;
  }
}

}  // namespace smachac
