// The small-object heap (tools/smachac/small_object_heap.h), linked into this test as into the
// smachac executable, so every new and delete here goes through it: blocks never overlap
// (each is filled with its own pattern and checked before it is freed), are aligned as
// operator new promises, and stay usable across the small/large limit, a full region,
// deletes with and without a size, arrays, nothrow forms and other threads.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <random>
#include <thread>
#include <vector>

#include "tools/smachac/small_object_heap.h"

// The sized form, declared for compilers that leave it out without -fsized-deallocation (clang
// 14); small_object_heap.cpp defines it.
void operator delete(void* block, std::size_t bytes) noexcept;

namespace smachac::driver {
namespace {

struct Block {
  unsigned char* bytes;
  std::size_t size;
  unsigned char pattern;
};

Block allocateBlock(std::size_t size, unsigned char pattern) {
  auto* bytes = static_cast<unsigned char*>(::operator new(size));
  std::fill_n(bytes, size, pattern);
  return {bytes, size, pattern};
}

bool intact(const Block& block) {
  return std::all_of(block.bytes, block.bytes + block.size,
                     [&](unsigned char byte) { return byte == block.pattern; });
}

bool aligned(const void* pointer) {
  return reinterpret_cast<std::uintptr_t>(pointer) % __STDCPP_DEFAULT_NEW_ALIGNMENT__ == 0;
}

/// Frees `block` after checking it, with a size or without, alternately.
void freeBlock(const Block& block, bool sized) {
  CHECK(intact(block));
  if (sized) {
    ::operator delete(block.bytes, block.size);
  } else {
    ::operator delete(block.bytes);
  }
}

TEST_SUITE("small_object_heap") {
  TEST_CASE("random blocks on both sides of the limit never overlap and stay aligned") {
    enableSmallObjectHeap();
    std::mt19937 random(20261126);
    std::uniform_int_distribution<std::size_t> size_of(1, 2 * kLargestSmallBlock);
    std::vector<Block> live;
    for (int step = 0; step < 200000; ++step) {
      if (!live.empty() && random() % 3 == 0) {
        const std::size_t at = random() % live.size();
        freeBlock(live[at], step % 2 == 0);
        live[at] = live.back();
        live.pop_back();
      } else {
        live.push_back(allocateBlock(size_of(random), static_cast<unsigned char>(step)));
        CHECK(aligned(live.back().bytes));
      }
    }
    for (const Block& block : live) freeBlock(block, true);
  }

  TEST_CASE("more live blocks than the region holds fall back to malloc") {
    enableSmallObjectHeap();
    std::vector<Block> live;
    for (int i = 0; i < 64 * 1024; ++i) {  // 16 MiB of 256-byte blocks
      live.push_back(allocateBlock(256, static_cast<unsigned char>(i)));
    }
    for (std::size_t i = 0; i < live.size(); i += 2) freeBlock(live[i], false);
    for (std::size_t i = 0; i < live.size(); i += 2) live[i] = allocateBlock(48, 0xa5);
    for (const Block& block : live) freeBlock(block, false);
  }

  TEST_CASE("a freed block is handed out again for its size class") {
    enableSmallObjectHeap();
    void* first = ::operator new(40);
    ::operator delete(first, 40);
    void* again = ::operator new(33);  // the same 48-byte class
    CHECK(again == first);
    ::operator delete(again);
  }

  TEST_CASE("arrays, nothrow forms and zero-byte requests") {
    enableSmallObjectHeap();
    auto numbers = std::make_unique<int[]>(100);
    numbers[99] = 7;
    CHECK(numbers[99] == 7);
    void* nothrow_block = ::operator new(24, std::nothrow);
    REQUIRE(nothrow_block != nullptr);
    ::operator delete(nothrow_block, std::nothrow);
    void* empty1 = ::operator new(0);
    void* empty2 = ::operator new(0);
    CHECK(empty1 != nullptr);
    CHECK(empty1 != empty2);
    ::operator delete(empty1);
    ::operator delete(empty2);
    CHECK(::operator new(SIZE_MAX / 2, std::nothrow) == nullptr);
    CHECK_THROWS_AS(static_cast<void>(::operator new(SIZE_MAX / 2)), std::bad_alloc);
  }

  TEST_CASE("blocks cross threads both ways") {
    enableSmallObjectHeap();
    Block mine = allocateBlock(64, 0x11);
    Block theirs{};
    std::thread other([&] {
      theirs = allocateBlock(64, 0x22);  // not the heap's thread: from malloc
      freeBlock(mine, true);             // left unused, never touched again
    });
    other.join();
    freeBlock(theirs, false);
    std::vector<Block> after;
    for (int i = 0; i < 1000; ++i) after.push_back(allocateBlock(64, 0x33));
    for (const Block& block : after) freeBlock(block, true);
  }
}

}  // namespace
}  // namespace smachac::driver
