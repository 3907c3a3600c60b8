// readFileText: open (never blocking on a FIFO), check it is a regular file, read it whole,
// and report a failure at any step as nullopt. Plain POSIX calls: an ifstream copied through
// a stringstream cost ~10 K instructions a file, on a cold compile that reads several.
#include "ir/support/file_text.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

namespace smachac {

std::optional<std::string> readOpenFile(int fd, size_t expected_size) {
  std::string text(expected_size + 1, '\0');
  size_t length = 0;
  while (true) {
    if (length == text.size()) text.resize(text.size() * 2);
    ssize_t got = ::read(fd, text.data() + length, text.size() - length);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return std::nullopt;
    if (got == 0) break;
    length += static_cast<size_t>(got);
  }
  text.resize(length);
  return text;
}

std::optional<std::string> readFileText(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return std::nullopt;
  struct stat info;
  std::optional<std::string> text;
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode)) {
    text = readOpenFile(fd, static_cast<size_t>(info.st_size));
  }
  ::close(fd);
  return text;
}

}  // namespace smachac
