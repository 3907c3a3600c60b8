// Persistent worker threads of a Concurrence.
#include "child_workers.h"

namespace smachac::runtime {

ChildWorkers::~ChildWorkers() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void ChildWorkers::run(std::size_t n, const std::function<void(std::size_t)>& task) {
  {
    std::lock_guard lock(mutex_);
    // A new worker has seen the generations before this one.
    while (threads_.size() + 1 < n) {
      std::size_t index = threads_.size() + 1;
      threads_.emplace_back([this, index, seen = generation_] { work(index, seen); });
    }
    task_ = &task;
    children_ = n;
    pending_ = n - 1;
    ++generation_;
  }
  wake_.notify_all();
  task(0);
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return pending_ == 0; });
  task_ = nullptr;
}

void ChildWorkers::work(std::size_t index, uint64_t seen) {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    if (index >= children_) continue;
    const std::function<void(std::size_t)>& task = *task_;
    lock.unlock();
    task(index);
    lock.lock();
    if (--pending_ == 0) done_.notify_one();
  }
}

}  // namespace smachac::runtime
