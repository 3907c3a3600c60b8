// The file-system questions the loader asks about template directories, answered with POSIX
// calls on plain strings: std::filesystem paths split and copied their components on every
// question (a cold compile spent ~0.15 M instructions there), and a directory is listed with
// getdents64 into a buffer on the stack (opendir allocated 32 KiB per listing). Rules:
// answers match what std::filesystem gave (symbolic links followed, `.` and `..` never
// listed). A `Listings` keeps a directory's listing while the directory is provably the same
// (see below); every other answer is read afresh.
#pragma once

#include <cstdint>
#include <ctime>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace smachac::tmpl {

/// `dir/name` as std::filesystem::path(dir) / name spells it for a relative `name`: no
/// separator added after an empty `dir` or one ending in `/`.
std::string joinTemplatePath(std::string_view dir, std::string_view name);

/// `path` as std::filesystem::path::lexically_normal spells it (returned as it is when it
/// has no `.`, `..` or empty component to remove).
std::string lexicallyNormal(std::string path);

/// Whether `path` names a regular file (through symbolic links).
bool isRegularTemplateFile(const std::string& path);

/// Directory listings kept for reuse: a compile resolves several template
/// names against the same `-I` directory, and a listing costs an open, two getdents64 and a
/// close (about 14 µs here) where checking that it still holds costs one stat (about 1 µs).
/// A listing is reused only while the directory has the same device, inode and modification
/// time, and is kept only when that time is at least two seconds older than the listing
/// (changes within one timestamp tick cannot then go unseen) and no entry had to be
/// followed to know its type (a symbolic link's target may change without its directory).
class Listings {
 public:
  /// The names of the regular files in directory `dir`, in the order the directory lists
  /// them; empty when it cannot be read. Valid until the next call.
  const std::vector<std::string>& regularFilesIn(const std::string& dir);

 private:
  struct Listing {
    uint64_t device = 0;
    uint64_t inode = 0;
    timespec modified{};
    std::vector<std::string> names;
  };
  std::map<std::string, Listing, std::less<>> kept_;
  std::vector<std::string> unkept_;  // the last listing that could not be kept
};

}  // namespace smachac::tmpl
