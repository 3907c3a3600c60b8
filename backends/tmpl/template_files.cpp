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

/// Appends the regular files among the entries getdents64 wrote into `chunk`; `followed` is
/// set when an entry's type had to be found through its path.
void addRegularFiles(const std::string& dir, const char* chunk, size_t bytes,
                     std::vector<std::string>& names, bool& followed) {
  for (size_t at = 0; at < bytes;) {
    const auto* entry = reinterpret_cast<const dirent64*>(chunk + at);
    at += entry->d_reclen;
    if (isDotEntry(entry->d_name)) continue;
    followed = followed || entry->d_type == DT_LNK || entry->d_type == DT_UNKNOWN;
    if (isRegularEntry(dir, *entry)) names.emplace_back(entry->d_name);
  }
}

/// Lists the open directory `fd` (of path `dir`) into `names`; whether an entry was followed.
bool listInto(int fd, const std::string& dir, std::vector<std::string>& names) {
  bool followed = false;
  alignas(dirent64) char chunk[kListingChunk];
  while (true) {
    ssize_t bytes = ::getdents64(fd, chunk, sizeof chunk);
    if (bytes <= 0) break;
    addRegularFiles(dir, chunk, static_cast<size_t>(bytes), names, followed);
  }
  return followed;
}

bool sameTime(const timespec& a, const timespec& b) {
  return a.tv_sec == b.tv_sec && a.tv_nsec == b.tv_nsec;
}

/// Whether a directory modified at `modified` is old enough for its listing to be kept.
bool settled(const timespec& modified) {
  constexpr time_t kSettleSeconds = 2;
  timespec now{};
  ::clock_gettime(CLOCK_REALTIME, &now);
  return modified.tv_sec + kSettleSeconds < now.tv_sec;
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

const std::vector<std::string>& Listings::regularFilesIn(const std::string& dir) {
  struct stat info;
  auto kept = kept_.find(dir);
  if (kept != kept_.end() && ::stat(dir.c_str(), &info) == 0 && S_ISDIR(info.st_mode) &&
      info.st_dev == kept->second.device && info.st_ino == kept->second.inode &&
      sameTime(info.st_mtim, kept->second.modified)) {
    return kept->second.names;
  }
  unkept_.clear();
  int fd = dir.empty() ? -1 : ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return unkept_;
  // The directory's state is taken before it is read: a change after that shows as a newer
  // modification time next time.
  bool known = ::fstat(fd, &info) == 0;
  bool followed = listInto(fd, dir, unkept_);
  ::close(fd);
  if (!known || followed || !settled(info.st_mtim)) return unkept_;
  Listing& listing = kept_[dir];
  listing = {info.st_dev, info.st_ino, info.st_mtim, std::move(unkept_)};
  unkept_.clear();
  return listing.names;
}

}  // namespace smachac::tmpl
