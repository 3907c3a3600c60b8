// The smachac executable's global operator new and delete: small blocks (up to
// kLargestSmallBlock bytes) come from free lists by size class, refilled from a region mapped
// once, where glibc's malloc spent about a quarter of a cold compile's instructions on a heap
// that grows from nothing. Rules: only the thread that enabled the heap uses it (a small block
// freed on another thread is left unused, never touched); larger blocks, every block before
// the heap is enabled or after its region is full, and every block of sanitizer builds (which
// keep the standard operators) come from malloc; the region is never handed back.
#pragma once

#include <cstddef>

namespace smachac::driver {

inline constexpr std::size_t kLargestSmallBlock = 512;

/// Lets the calling thread allocate small blocks from the heap from now on, unless another
/// thread did so first (`smachac lsp`, whose threads share the documents, does not call it).
void enableSmallObjectHeap();

}  // namespace smachac::driver
