// Huge pages for a big script's heap (tools/smachac/huge_pages.h), linked into this test with
// the small-object heap as into the smachac executable: a small script leaves the mappings
// alone; once a big one asked, blocks with mappings of their own and the grown heap are
// advised (VmFlags `hg` in /proc/self/smaps), and the blocks stay usable.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tools/smachac/huge_pages.h"

namespace smachac::driver {
namespace {

namespace fs = std::filesystem;

/// Whether the mapping holding `address` is advised MADV_HUGEPAGE.
bool advised(const void* address) {
  auto where = reinterpret_cast<uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    uintptr_t from = 0;
    uintptr_t to = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> from >> dash >> to && dash == '-') {
      inside = from <= where && where < to;
    } else if (inside && line.starts_with("VmFlags:")) {
      return line.find(" hg") != std::string::npos;
    }
  }
  return false;
}

std::string scriptOfSize(const char* name, size_t bytes) {
  fs::path path = fs::temp_directory_path() / name;
  std::ofstream(path) << std::string(bytes, '#');
  return path.string();
}

TEST_CASE("a big script's blocks with mappings of their own get huge pages, not before") {
  constexpr size_t kBlock = kMappedBlockBytes * 8;
  std::string small = scriptOfSize("smachac_huge_pages_small.yml", kHugePageScriptBytes - 1);
  std::string big = scriptOfSize("smachac_huge_pages_big.yml", kHugePageScriptBytes);
  preferHugePagesFor("/nonexistent/script.yml");
  preferHugePagesFor(small);
  auto* before = static_cast<char*>(::operator new(kBlock));
  CHECK_FALSE(advised(before + kBlock / 2));
  preferHugePagesFor(big);
  auto* after = static_cast<char*>(::operator new(kBlock));
  std::fill_n(after, kBlock, 'x');
  CHECK(after[kBlock - 1] == 'x');
  if (fs::exists("/sys/kernel/mm/transparent_hugepage/enabled")) {
    CHECK(advised(after + kBlock / 2));
  }
  ::operator delete(before);
  ::operator delete(after);
  fs::remove(small);
  fs::remove(big);
}

}  // namespace
}  // namespace smachac::driver
