// Persistent worker threads of a Concurrence, and children taken in order by whichever thread
// is free (child_workers.h).
#include "child_workers.h"

#include <mutex>

namespace smachac::runtime {

ChildWorkers::~ChildWorkers() {
  stop_.store(true);
  for (Worker& worker : workers_) wake(worker);
  for (Worker& worker : workers_) worker.thread.join();
}

void ChildWorkers::startWorkers(std::size_t count) {
  while (workers_.size() < count) {
    Worker& worker = workers_.emplace_back();
    try {
      worker.thread = std::thread([this, &worker] { work(worker); });
    } catch (...) {
      workers_.pop_back();
      throw;
    }
  }
}

void ChildWorkers::run(std::size_t n, const std::function<void(std::size_t)>& task) {
  if (n == 0) return;
  startWorkers(n - 1);
  Worker* first = nullptr;
  {
    std::lock_guard lock(mutex_);
    task_ = &task;
    children_ = n;
    next_ = 1;  // child 0 is this thread's
    woken_ = 0;
    unfinished_.store(n);
    if (n > 1) first = nextToWakeLocked();
  }
  if (first != nullptr) wake(*first);
  task(0);
  unfinished_.fetch_sub(1);
  drain(false);
  for (std::size_t left = unfinished_.load(); left != 0; left = unfinished_.load()) {
    unfinished_.wait(left);
  }
}

void ChildWorkers::drain(bool wake_next) {
  for (;;) {
    std::size_t index = 0;
    const std::function<void(std::size_t)>* task = nullptr;
    Worker* next = nullptr;
    {
      std::lock_guard lock(mutex_);
      if (next_ >= children_) return;
      index = next_++;
      task = task_;
      if (wake_next && next_ < children_) next = nextToWakeLocked();
    }
    if (next != nullptr) wake(*next);
    (*task)(index);
    if (unfinished_.fetch_sub(1) == 1) unfinished_.notify_one();
  }
}

ChildWorkers::Worker* ChildWorkers::nextToWakeLocked() {
  if (woken_ >= workers_.size()) return nullptr;
  return &workers_[woken_++];
}

void ChildWorkers::wake(Worker& worker) {
  worker.wakes.fetch_add(1);
  worker.wakes.notify_one();
}

void ChildWorkers::work(Worker& self) {
  uint32_t seen = 0;
  for (;;) {
    self.wakes.wait(seen);
    seen = self.wakes.load();
    if (stop_.load()) return;
    drain(true);
  }
}

}  // namespace smachac::runtime
