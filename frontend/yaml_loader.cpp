// YAML file → ir::Value with locations, on yaml-cpp.
#include "frontend/yaml_loader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include "frontend/yaml_events.h"
#include "ir/support/file_text.h"
#include "ir/support/utf8.h"

namespace smachac::frontend {
namespace {

/// Reports why `path` could not be opened: stat tells a missing file from one that is there
/// but cannot be read.
void reportUnopenable(const std::string& path, SourceLoc from, DiagnosticEmitter& diags) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    diags.emit<DiagKind::FileNotFound>(from, path, "no such file");
  } else if (S_ISDIR(info.st_mode)) {
    diags.emit<DiagKind::UnreadableFile>(from, path, "it is a directory");
  } else if (!S_ISREG(info.st_mode)) {
    diags.emit<DiagKind::UnreadableFile>(from, path, "it is not a regular file");
  } else {
    diags.emit<DiagKind::UnreadableFile>(from, path, "permission denied or unreadable");
  }
}

/// The text of the open file `fd` when it is a regular file of at most kMaxScriptBytes.
std::optional<std::string> readOpened(int fd, const std::string& path, SourceLoc from,
                                      DiagnosticEmitter& diags) {
  struct stat info {};
  const char* problem = nullptr;
  if (::fstat(fd, &info) != 0) {
    problem = "permission denied or unreadable";
  } else if (S_ISDIR(info.st_mode)) {
    problem = "it is a directory";
  } else if (!S_ISREG(info.st_mode)) {
    problem = "it is not a regular file";
  } else if (static_cast<uintmax_t>(info.st_size) > kMaxScriptBytes) {
    diags.emit<DiagKind::FileTooLarge>(from, path, std::to_string(info.st_size), kMaxScriptBytes);
    return std::nullopt;
  }
  std::optional<std::string> text;
  if (!problem) text = readOpenFile(fd, static_cast<size_t>(info.st_size));
  if (!text) {
    diags.emit<DiagKind::UnreadableFile>(from, path,
                                         problem ? problem : "permission denied or unreadable");
  }
  return text;
}

/// A script's text: one open and one fstat (never blocking on a FIFO); the reasons a file
/// cannot be read are told apart as a stat would tell them.
std::optional<std::string> readRegularFile(const std::string& path, SourceLoc from,
                                           DiagnosticEmitter& diags) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    reportUnopenable(path, from, diags);
    return std::nullopt;
  }
  std::optional<std::string> text = readOpened(fd, path, from, diags);
  ::close(fd);
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
