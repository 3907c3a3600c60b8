// Atomic file output.
#include "tools/smachac/output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>

namespace smachac::driver {
namespace {

namespace fs = std::filesystem;

std::string errnoText() { return std::strerror(errno); }

std::optional<std::string> writeAll(int fd, const std::string& content) {
  size_t written = 0;
  while (written < content.size()) {
    ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errnoText();
    written += static_cast<size_t>(n);
  }
  return std::nullopt;
}

/// A destination's content written to a temporary file next to it, not yet renamed; or, for
/// a destination that exists and is no regular file (`/dev/null`, a FIFO), the content to
/// write into it: renaming over a device would replace it with a file.
struct StagedFile {
  std::string path;
  std::string temporary;  ///< empty: written directly
  const std::string* direct_content = nullptr;
  bool replaces_file = false;  ///< the destination is a regular file (exchanged, not renamed over)
};

/// The destination's type (S_IFMT bits), 0 if there is none.
mode_t destinationType(const std::string& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0 ? info.st_mode & S_IFMT : 0;
}

bool isSpecialFile(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

// Puts the staged file in place of an existing regular file by exchanging the two names, then
// removes the old content: as atomic as a rename over it (the path always names a whole file),
// but ext4 writes back a file renamed over another at the rename (auto_da_alloc), which cost
// 0.14-0.28 ms a compile here on an idle disk and milliseconds on a busy one. Elsewhere, or
// where the exchange is not supported, a rename.
int replace(const StagedFile& file) {
  const char* staged = file.temporary.c_str();
  const char* path = file.path.c_str();
  if (file.replaces_file && ::renameat2(AT_FDCWD, staged, AT_FDCWD, path, RENAME_EXCHANGE) == 0) {
    // `staged` now names the previous content; if that was no longer a file (a directory put
    // there since), exchange back and let the rename report it.
    if (::unlink(staged) == 0) return 0;
    ::renameat2(AT_FDCWD, staged, AT_FDCWD, path, RENAME_EXCHANGE);
  }
  return ::rename(staged, path);
}

std::optional<std::string> writeDirectly(const StagedFile& file) {
  int fd = ::open(file.path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) return "cannot write `" + file.path + "`: " + errnoText();
  std::optional<std::string> error = writeAll(fd, *file.direct_content);
  if (::close(fd) != 0 && !error) error = errnoText();
  if (error) return "cannot write `" + file.path + "`: " + *error;
  return std::nullopt;
}

std::optional<std::string> commit(const StagedFile& file) {
  if (file.direct_content) return writeDirectly(file);
  if (replace(file) != 0) {
    return "cannot write `" + file.path + "`: " + errnoText();
  }
  return std::nullopt;
}

std::optional<std::string> stage(const std::string& path, const std::string& content,
                                 StagedFile& staged) {
  if (isSpecialFile(path)) {
    staged = {path, "", &content};
    return std::nullopt;
  }
  fs::path target(path);
  fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::string pattern = (dir / ("." + target.filename().string() + ".tmp.XXXXXX")).string();
  int fd = ::mkstemp(pattern.data());
  if (fd < 0) return "cannot create a file in `" + dir.string() + "`: " + errnoText();
  std::optional<std::string> error = writeAll(fd, content);
  mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(fd, 0666 & ~mask) != 0 && !error) error = errnoText();
  if (::close(fd) != 0 && !error) error = errnoText();
  if (error) {
    ::unlink(pattern.c_str());
    return "cannot write `" + path + "`: " + *error;
  }
  staged = {path, pattern, nullptr, destinationType(path) == S_IFREG};
  return std::nullopt;
}

void discard(const std::vector<StagedFile>& staged) {
  for (const StagedFile& file : staged) {
    if (!file.temporary.empty()) ::unlink(file.temporary.c_str());
  }
}

}  // namespace

std::optional<std::string> writeFileAtomically(const std::string& path,
                                               const std::string& content) {
  if (path == "-") {
    std::fwrite(content.data(), 1, content.size(), stdout);
    std::fflush(stdout);
    return std::nullopt;
  }
  return writeFilesAtomically({{path, content}});
}

std::optional<std::string> writeFilesAtomically(
    const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<StagedFile> staged;
  for (const auto& [path, content] : files) {
    StagedFile file;
    if (std::optional<std::string> error = stage(path, content, file)) {
      discard(staged);
      return error;
    }
    staged.push_back(std::move(file));
  }
  for (size_t i = 0; i < staged.size(); ++i) {
    if (std::optional<std::string> error = commit(staged[i])) {
      discard({staged.begin() + static_cast<std::ptrdiff_t>(i), staged.end()});
      return error;
    }
  }
  return std::nullopt;
}

}  // namespace smachac::driver
