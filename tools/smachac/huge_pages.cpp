// The heap reservation of huge_pages.h. glibc's malloc grows its heap with sbrk and has no
// call to ask for huge pages there (only the GLIBC_TUNABLES variable, read at start-up). So
// the top pad (M_TOP_PAD: what every growth of the heap adds beyond the request, and what a
// shrink keeps) is raised to the room a big script needs, one block that the heap's top
// cannot hold makes the heap grow by that much, and the grown range, untouched yet, is
// advised MADV_HUGEPAGE. Pages untouched stay unmapped, so the peak RSS does not change
// much (flat 100k: lint 117 -> 125 MB, compile 122 -> 127 MB). The blocks of a megabyte and
// more (the script's text, the code buffers and the output: mappings of their own) are
// advised as they are allocated (small_object_heap.cpp calls adviseHugePages).
#include "tools/smachac/huge_pages.h"

#if !defined(SMACHAC_SANITIZED)
#include <malloc.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#endif

namespace smachac::driver {

#if defined(SMACHAC_SANITIZED)
void preferHugePagesFor(const std::string&) {}  // the sanitizers' allocators: left alone
void adviseHugePages(void*, size_t) {}
#else
namespace {

constexpr size_t kHugePage = size_t{2} << 20;
/// Heap room a byte of script takes at most: the flat 100k script (18 MB) grows the heap to
/// 78 MB, compile or lint.
constexpr size_t kHeapBytesPerScriptByte = 8;
constexpr size_t kMaxReserve = size_t{1} << 30;  // M_TOP_PAD is an int
/// Below main.cpp's M_MMAP_THRESHOLD: a block the heap's top holds, or grows for.
constexpr size_t kGrowBlock = kMappedBlockBytes - 4096;

bool g_reserved = false;

/// Asks for huge pages for the whole huge pages inside [from, end).
void advise(uintptr_t from, uintptr_t end) {
  from = (from + kHugePage - 1) & ~(kHugePage - 1);
  if (end > from) madvise(reinterpret_cast<void*>(from), end - from, MADV_HUGEPAGE);
}

}  // namespace

void adviseHugePages(void* block, size_t bytes) {
  if (!g_reserved) return;
  auto from = reinterpret_cast<uintptr_t>(block);
  advise(from, from + bytes);
}

void preferHugePagesFor(const std::string& path) {
  struct stat info;
  if (g_reserved || stat(path.c_str(), &info) != 0) return;
  auto bytes = static_cast<size_t>(std::max<off_t>(info.st_size, 0));
  if (bytes < kHugePageScriptBytes) return;
  g_reserved = true;
  const size_t reserve = std::min(bytes * kHeapBytesPerScriptByte, kMaxReserve);
  if (mallopt(M_TOP_PAD, static_cast<int>(reserve)) == 0) return;
  void* block = std::malloc(kGrowBlock);
  if (!block) return;
  advise(reinterpret_cast<uintptr_t>(block) + kGrowBlock, reinterpret_cast<uintptr_t>(sbrk(0)));
  std::free(block);
}
#endif

}  // namespace smachac::driver
