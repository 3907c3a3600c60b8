// Transparent huge pages for the heap of a big script's compile or lint: each 4 KiB page the
// heap touches first is a page fault, and the flat 100,000-state script of bench/compare took
// 30,000 of them (with the kernel clearing each page, a fifth of its lint's wall time). Where
// the system gives huge pages on request only (`madvise` in
// /sys/kernel/mm/transparent_hugepage/enabled, Debian's default), the heap asks for them.
#pragma once

#include <cstddef>
#include <string>

namespace smachac::driver {

/// Scripts from this size on (about 5,500 states of bench/compare's flat script) get a heap
/// of huge pages; smaller ones never change the heap.
inline constexpr size_t kHugePageScriptBytes = size_t{1} << 20;

/// Before compiling the script at `path`: when it is big, reserves heap room in proportion to
/// it and asks for huge pages there (once a process; no effect on a failure of any kind).
void preferHugePagesFor(const std::string& path);

/// Blocks from this size on have mappings of their own (main.cpp's M_MMAP_THRESHOLD).
inline constexpr size_t kMappedBlockBytes = size_t{1} << 20;

/// After a big script asked for huge pages: asks for them for a block of `bytes` (at least
/// kMappedBlockBytes) just allocated, a mapping of its own that nothing touched yet.
void adviseHugePages(void* block, size_t bytes);

}  // namespace smachac::driver
