// POSIX answers for the template loader (template_files.h).
#include "backends/tmpl/template_files.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

namespace smachac::tmpl {
namespace {

/// The bytes of directory entries read at once: a listing reads into the stack, where
/// opendir allocated a 32 KiB buffer on the heap for every listing.
constexpr size_t kListingChunk = 4096;

bool isDotEntry(std::string_view name) { return name == "." || name == ".."; }

/// Whether a directory entry is a regular file: its type when the directory says, else (a
/// symbolic link, an unknown type) the type of what its path leads to.
bool isRegularEntry(const std::string& dir, const dirent64& entry) {
  if (entry.d_type == DT_REG) return true;
  if (entry.d_type != DT_LNK && entry.d_type != DT_UNKNOWN) return false;
  return isRegularTemplateFile(joinTemplatePath(dir, entry.d_name));
}

/// Appends the regular files among the entries getdents64 wrote into `chunk`.
void addRegularFiles(const std::string& dir, const char* chunk, size_t bytes,
                     std::vector<std::string>& names) {
  for (size_t at = 0; at < bytes;) {
    const auto* entry = reinterpret_cast<const dirent64*>(chunk + at);
    at += entry->d_reclen;
    if (!isDotEntry(entry->d_name) && isRegularEntry(dir, *entry))
      names.emplace_back(entry->d_name);
  }
}

/// Whether lexically_normal would leave `path` as it is: no empty component (a doubled or
/// trailing `/`), no `.` or `..` component.
bool isPlainPath(std::string_view path) {
  size_t start = path.starts_with('/') ? 1 : 0;
  while (start <= path.size()) {
    size_t end = std::min(path.find('/', start), path.size());
    std::string_view piece = path.substr(start, end - start);
    if (piece.empty() || isDotEntry(piece)) return false;
    start = end + 1;
  }
  return true;
}

}  // namespace

std::string joinTemplatePath(std::string_view dir, std::string_view name) {
  std::string path(dir);
  if (!path.empty() && path.back() != '/') path += '/';
  path += name;
  return path;
}

std::string lexicallyNormal(std::string path) {
  if (isPlainPath(path)) return path;
  return std::filesystem::path(path).lexically_normal().string();
}

bool isRegularTemplateFile(const std::string& path) {
  struct stat info;
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

std::vector<std::string> regularFilesIn(const std::string& dir) {
  std::vector<std::string> names;
  int fd = dir.empty() ? -1 : ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return names;
  alignas(dirent64) char chunk[kListingChunk];
  while (true) {
    ssize_t bytes = ::getdents64(fd, chunk, sizeof chunk);
    if (bytes <= 0) break;
    addRegularFiles(dir, chunk, static_cast<size_t>(bytes), names);
  }
  ::close(fd);
  return names;
}

}  // namespace smachac::tmpl
