// YAML file → ir::Value with locations, on yaml-cpp.
#include "frontend/yaml_loader.h"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>

#include "frontend/yaml_events.h"
#include "ir/support/utf8.h"

namespace smachac::frontend {
namespace {

namespace fs = std::filesystem;

std::optional<std::string> readRegularFile(const std::string& path, SourceLoc from,
                                           DiagnosticEmitter& diags) {
  std::error_code ec;
  fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    diags.emit<DiagKind::FileNotFound>(from, path, "no such file");
    return std::nullopt;
  }
  if (!fs::is_regular_file(status)) {
    diags.emit<DiagKind::UnreadableFile>(
        from, path, fs::is_directory(status) ? "it is a directory" : "it is not a regular file");
    return std::nullopt;
  }
  uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > kMaxScriptBytes) {
    diags.emit<DiagKind::FileTooLarge>(from, path, std::to_string(size), kMaxScriptBytes);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diags.emit<DiagKind::UnreadableFile>(from, path, "permission denied or unreadable");
    return std::nullopt;
  }
  std::string text;
  if (!ec) text.reserve(size);
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) text.append(chunk, in.gcount());
  return text;
}

}  // namespace

std::optional<ir::Value> parseYaml(uint32_t file, const SourceManager& sources,
                                   DiagnosticEmitter& diags) {
  std::string_view text = sources.content(file);
  if (std::optional<size_t> bad = findInvalidUtf8(text)) {
    bool nul = text[*bad] == '\0';
    diags.emit<DiagKind::InvalidEncoding>(
        sources.locOf(file, *bad), nul ? EncodingProblem::NulByte : EncodingProblem::InvalidUtf8);
    return std::nullopt;
  }
  return buildYamlValue(file, text, diags);
}

uint32_t readYamlFile(const std::string& path, SourceLoc from, SourceManager& sources,
                      DiagnosticEmitter& diags) {
  std::optional<std::string> text = readRegularFile(path, from, diags);
  if (!text) return 0;
  return sources.addFile(path, std::move(*text));
}

LoadedYaml loadYamlFile(const std::string& path, SourceLoc from, SourceManager& sources,
                        DiagnosticEmitter& diags) {
  uint32_t file = readYamlFile(path, from, sources, diags);
  if (file == 0) return {};
  return {file, parseYaml(file, sources, diags)};
}

}  // namespace smachac::frontend
