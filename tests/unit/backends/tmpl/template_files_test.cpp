// Kept directory listings (backends/tmpl/template_files.h): a listing is reused only while
// its directory is unchanged and settled, so files added or removed are always seen.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "backends/tmpl/template_files.h"

namespace smachac::tmpl {
namespace {

namespace fs = std::filesystem;

/// A fresh directory under the system's temporary one, removed at the end of the test.
struct TempDir {
  fs::path path;
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "smachac_listing_XXXXXX").string();
    REQUIRE(::mkdtemp(pattern.data()) != nullptr);  // pattern now names the new directory
    path = pattern;
  }
  ~TempDir() { fs::remove_all(path); }
  void add(const std::string& name) const { std::ofstream(path / name) << "x"; }
  /// Sets the directory's access and modification times to `seconds` after the epoch.
  void setModified(time_t seconds) const {
    timespec times[2] = {{seconds, 0}, {seconds, 0}};
    ::utimensat(AT_FDCWD, path.c_str(), times, 0);
  }
};

std::vector<std::string> sorted(std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  return names;
}

TEST_CASE("a kept listing is replaced when its directory changes") {
  TempDir dir;
  dir.add("A.tpl.py");
  fs::create_directory(dir.path / "sub");
  dir.setModified(1'000'000'000);
  Listings listings;
  CHECK(sorted(listings.regularFilesIn(dir.path.string())) == std::vector<std::string>{"A.tpl.py"});
  dir.add("B.tpl.py");  // the directory's modification time becomes now
  CHECK(sorted(listings.regularFilesIn(dir.path.string())) ==
        std::vector<std::string>{"A.tpl.py", "B.tpl.py"});
  fs::remove(dir.path / "A.tpl.py");
  dir.setModified(1'000'000'001);  // settled again, but not the time the kept listing saw
  CHECK(sorted(listings.regularFilesIn(dir.path.string())) == std::vector<std::string>{"B.tpl.py"});
}

TEST_CASE("a directory changed within the last seconds is read afresh every time") {
  TempDir dir;
  dir.add("A.tpl.py");
  Listings listings;
  CHECK(listings.regularFilesIn(dir.path.string()).size() == 1);
  // Within the same timestamp tick the modification time may not move: only an unkept
  // listing sees this file for certain.
  dir.add("B.tpl.py");
  CHECK(listings.regularFilesIn(dir.path.string()).size() == 2);
}

TEST_CASE("a listing that followed a symbolic link is not kept") {
  TempDir dir;
  dir.add("target");
  fs::create_symlink(dir.path / "target", dir.path / "Link.tpl.py");
  dir.setModified(1'000'000'000);
  Listings listings;
  CHECK(listings.regularFilesIn(dir.path.string()).size() == 2);
  fs::remove(dir.path / "target");  // the link dangles
  dir.setModified(1'000'000'000);   // and the directory shows the time the listing saw
  CHECK(listings.regularFilesIn(dir.path.string()).empty());
}

TEST_CASE("a missing directory lists nothing") {
  Listings listings;
  CHECK(listings.regularFilesIn("/nonexistent/smachac/templates").empty());
  CHECK(listings.regularFilesIn("").empty());
}

}  // namespace
}  // namespace smachac::tmpl
