// The process-wide pool behind ir::Symbol: one kept copy of each distinct text, found through
// an open-addressing table (a big script interns a few names a state, so a lookup is kept
// short: one FNV-1a hash of a short name and a probe or two).
#include "ir/symbol.h"

#include <cstdint>
#include <deque>
#include <memory_resource>
#include <mutex>
#include <vector>

namespace smachac::ir {
namespace {

/// The text of every empty Symbol (made on first use: a Symbol may be made during static
/// initialisation).
const std::string& emptyText() {
  static const std::string kEmpty;
  return kEmpty;
}

uint64_t hashText(std::string_view text) {
  uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  return hash;
}

/// The kept texts (a deque: their addresses never move) in blocks of their own: were they
/// spread among the IR's allocations, they would keep its pages from being given back to the
/// system when the IR is freed. `slots` is a power-of-two table of them, at most half full.
class SymbolPool {
 public:
  const std::string* intern(std::string_view text, uint64_t hash) {
    std::lock_guard<std::mutex> lock(mutex_);
    size_t slot = find(text, hash);
    if (slots_[slot]) return slots_[slot];
    const std::string* kept = &texts_.emplace_back(text);
    slots_[slot] = kept;
    if (texts_.size() * 2 > slots_.size()) grow();
    return kept;
  }

 private:
  /// The slot holding `text`, or the empty slot where it goes.
  size_t find(std::string_view text, uint64_t hash) const {
    size_t mask = slots_.size() - 1;
    size_t slot = hash & mask;
    while (slots_[slot] && *slots_[slot] != text) slot = (slot + 1) & mask;
    return slot;
  }

  void grow() {
    slots_.assign(slots_.size() * 2, nullptr);
    for (const std::string& kept : texts_) slots_[find(kept, hashText(kept))] = &kept;
  }

  std::mutex mutex_;
  std::pmr::monotonic_buffer_resource blocks_{size_t{64} << 10};
  std::pmr::deque<std::string> texts_{&blocks_};
  std::vector<const std::string*> slots_ = std::vector<const std::string*>(1024);
};

/// Each thread remembers the last text interned in each of kRecentSlots slots (by hash): most
/// names recur (outcomes, keys, templates, the next state's name), and a hit there takes no
/// lock and no probe. The pool never frees a text, so a remembered one stays valid.
constexpr size_t kRecentSlots = 256;

/// Never destroyed: symbols held by other objects of static storage outlive every destructor.
SymbolPool& pool() {
  static SymbolPool* const kPool = new SymbolPool;
  return *kPool;
}

}  // namespace

Symbol::Symbol() : text_(&emptyText()) {}

const std::string* Symbol::intern(std::string_view text) {
  if (text.empty()) return &emptyText();
  thread_local const std::string* recent[kRecentSlots] = {};
  uint64_t hash = hashText(text);
  const std::string*& remembered = recent[hash % kRecentSlots];
  if (!remembered || *remembered != text) remembered = pool().intern(text, hash);
  return remembered;
}

}  // namespace smachac::ir
