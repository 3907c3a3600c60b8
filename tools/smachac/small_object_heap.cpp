// Global operator new and delete on the small-object heap (small_object_heap.h). The region
// is cut into runs of kRunBytes, taken in order, each holding blocks of one size class; a
// block's class is its run's, so blocks carry no header and a delete without a size finds it
// too. A class takes blocks from its free list first, then from the rest of its current run,
// then from a new run. Runs are small so that the classes share pages: a compile uses about
// 30 classes, and a page of its own for each (64 KiB spans) touched 14 more pages than its
// 104 KB of blocks need. All state is one zero-initialised global: no static constructor
// runs for it.
#include "tools/smachac/small_object_heap.h"

#include "tools/smachac/huge_pages.h"

#ifndef SMACHAC_SANITIZED
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>
#endif

namespace smachac::driver {

#ifdef SMACHAC_SANITIZED
void enableSmallObjectHeap() {}  // the sanitizers keep the standard operators
#else
namespace {

constexpr std::size_t kGranule = 16;  // every block is aligned as operator new promises
constexpr std::size_t kClasses = kLargestSmallBlock / kGranule;
constexpr std::size_t kRunBytes = 1024;
// Room for a typical compile's small blocks (about 0.1 MB). A big script's compile fills it
// and goes on with malloc: with 4 MiB or more the flat 10k and 100k compiles ran 2% slower
// than on malloc alone (their blocks spread over the classes' runs), with 1 MiB 1% faster.
constexpr std::size_t kRegionBytes = std::size_t{1} << 20;
constexpr std::size_t kRuns = kRegionBytes / kRunBytes;

struct FreeBlock {
  FreeBlock* next;
};

struct SmallObjectHeap {
  bool enabled;  // by some thread, which owns it
  char* region;  // mapped on the first small block
  std::size_t runs_used;
  uint8_t run_class[kRuns];
  FreeBlock* free_blocks[kClasses];
  char* next_block[kClasses];  // in the class's current run
  char* run_end[kClasses];
};

SmallObjectHeap g_heap;
thread_local bool t_owner = false;  // this thread enabled the heap (one load, no call)
// The owner still takes small blocks: not once the region is full (or could not be mapped),
// after which a compile's blocks come from malloc as directly as the heap allows.
thread_local bool t_allocating = false;

std::size_t classOf(std::size_t bytes) { return (bytes - 1) / kGranule; }

std::size_t blockBytes(std::size_t size_class) { return (size_class + 1) * kGranule; }

bool mapRegion() {
  void* region = mmap(nullptr, kRegionBytes, PROT_READ | PROT_WRITE,
                      MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (region == MAP_FAILED) {
    t_allocating = false;
    return false;
  }
  g_heap.region = static_cast<char*>(region);
  return true;
}

/// Starts a new run for `size_class`; false when the region is full or cannot be mapped.
bool startRun(std::size_t size_class) {
  if (!g_heap.region && !mapRegion()) return false;
  if (g_heap.runs_used == kRuns) {
    t_allocating = false;
    return false;
  }
  char* run = g_heap.region + g_heap.runs_used * kRunBytes;
  g_heap.run_class[g_heap.runs_used++] = static_cast<uint8_t>(size_class);
  g_heap.next_block[size_class] = run;
  g_heap.run_end[size_class] = run + kRunBytes;
  return true;
}

/// A block of `size_class`, or nullptr when the region has no room left.
void* takeBlock(std::size_t size_class) {
  if (FreeBlock* block = g_heap.free_blocks[size_class]) {
    g_heap.free_blocks[size_class] = block->next;
    return block;
  }
  const std::size_t bytes = blockBytes(size_class);
  if (static_cast<std::size_t>(g_heap.run_end[size_class] - g_heap.next_block[size_class]) <
          bytes &&
      !startRun(size_class)) {
    return nullptr;
  }
  char* block = g_heap.next_block[size_class];
  g_heap.next_block[size_class] = block + bytes;
  return block;
}

/// What the standard operator new does: malloc, calling the new-handler until it succeeds.
/// A block with a mapping of its own may get huge pages (huge_pages.h).
void* allocateLarge(std::size_t bytes) {
  if (bytes == 0) bytes = 1;
  while (true) {
    if (void* block = std::malloc(bytes)) {
      if (bytes >= kMappedBlockBytes) adviseHugePages(block, bytes);
      return block;
    }
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

/// Everything but a small block from a free list or the class's current run: kept out of
/// line, so that the common cases set up no frame.
[[gnu::noinline]] void* allocateUncommon(std::size_t bytes) {
  if (bytes - 1 < kLargestSmallBlock && t_allocating) {
    if (void* block = takeBlock(classOf(bytes))) return block;
  }
  return allocateLarge(bytes);
}

inline void* allocate(std::size_t bytes) {
  const std::size_t size_class = classOf(bytes);  // huge for 0 bytes
  if (size_class < kClasses && t_allocating) {
    if (FreeBlock* block = g_heap.free_blocks[size_class]) {
      g_heap.free_blocks[size_class] = block->next;
      return block;
    }
    char* block = g_heap.next_block[size_class];
    const std::size_t block_bytes = blockBytes(size_class);
    if (static_cast<std::size_t>(g_heap.run_end[size_class] - block) >= block_bytes) {
      g_heap.next_block[size_class] = block + block_bytes;
      return block;
    }
  }
  return allocateUncommon(bytes);
}

inline void release(void* block) noexcept {
  const std::uintptr_t offset =
      reinterpret_cast<std::uintptr_t>(block) - reinterpret_cast<std::uintptr_t>(g_heap.region);
  if (offset >= kRegionBytes || !g_heap.region) {
    std::free(block);  // also a null block
    return;
  }
  if (!t_owner) return;  // left unused: the owner's free lists are not shared
  const std::size_t size_class = g_heap.run_class[offset / kRunBytes];
  auto* freed = static_cast<FreeBlock*>(block);
  freed->next = g_heap.free_blocks[size_class];
  g_heap.free_blocks[size_class] = freed;
}

void* allocateNoThrow(std::size_t bytes) noexcept {
  try {
    return allocate(bytes);
  } catch (...) {
    return nullptr;
  }
}

}  // namespace

void enableSmallObjectHeap() {
  if (g_heap.enabled) return;  // owned already (by this thread or another)
  g_heap.enabled = true;
  t_owner = true;
  t_allocating = true;
}
#endif

}  // namespace smachac::driver

#ifndef SMACHAC_SANITIZED
using smachac::driver::allocate;
using smachac::driver::allocateNoThrow;
using smachac::driver::release;

void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
  return allocateNoThrow(bytes);
}
void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept {
  return allocateNoThrow(bytes);
}
void operator delete(void* block) noexcept { release(block); }
void operator delete[](void* block) noexcept { release(block); }
void operator delete(void* block, std::size_t) noexcept { release(block); }
void operator delete[](void* block, std::size_t) noexcept { release(block); }
void operator delete(void* block, const std::nothrow_t&) noexcept { release(block); }
void operator delete[](void* block, const std::nothrow_t&) noexcept { release(block); }
#endif
