// The arena that owns a template's syntax tree: nodes are placed one after another in large
// chunks (one allocation per chunk rather than per node, which was a sixth of compiling a
// template) and destroyed, newest first, with the arena. Nodes never move and are never freed
// one by one; a node larger than a chunk gets a chunk of its own.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace smachac::tmpl {

struct Expr;
struct Stmt;

class Arena {
 public:
  Arena() = default;
  Arena(const Arena&) = delete;
  Arena& operator=(const Arena&) = delete;
  ~Arena();

  template <class T, class... Args>
  T* make(Args&&... args) {
    T* node = new (allocate(sizeof(T), alignof(T))) T(std::forward<Args>(args)...);
    if constexpr (std::is_base_of_v<Expr, T>) {
      exprs_.push_back(node);
    } else {
      stmts_.push_back(node);
    }
    return node;
  }

 private:
  static constexpr size_t kChunkSize = 16 * 1024;

  void* allocate(size_t size, size_t align) {
    size_t start = (used_ + align - 1) & ~(align - 1);
    if (chunks_.empty() || start + size > capacity_) {
      capacity_ = size > kChunkSize ? size : kChunkSize;
      chunks_.push_back(std::make_unique_for_overwrite<std::byte[]>(capacity_));
      start = 0;
    }
    used_ = start + size;
    return chunks_.back().get() + start;
  }

  std::vector<std::unique_ptr<std::byte[]>> chunks_;
  size_t used_ = 0;
  size_t capacity_ = 0;
  std::vector<Expr*> exprs_;
  std::vector<Stmt*> stmts_;
};

}  // namespace smachac::tmpl
