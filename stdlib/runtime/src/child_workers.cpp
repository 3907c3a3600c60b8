// Persistent worker threads of a Concurrence, children taken in order by whichever thread is
// free, and workers woken only for children that block or run long (child_workers.h).
#include "child_workers.h"

#include <mutex>

namespace smachac::runtime {

namespace {

/// A run the thread is running a child of; the innermost is `running_run`, each links the
/// next one out (a child that is itself a Concurrence runs its children on the same thread).
struct RunningRun {
  ChildWorkers* workers;
  const RunningRun* outer;
};

thread_local const RunningRun* running_run = nullptr;

}  // namespace

ChildWorkers::~ChildWorkers() {
  watch_.stop();
  stop_.store(true);
  for (Worker& worker : workers_) wake(worker);
  for (Worker& worker : workers_) worker.thread.join();
}

void ChildWorkers::startThreads(std::size_t workers) {
  while (workers_.size() < workers) {
    Worker& worker = workers_.emplace_back();
    try {
      worker.thread = std::thread([this, &worker] { work(worker); });
    } catch (...) {
      workers_.pop_back();
      throw;
    }
  }
  watch_.start();
}

void ChildWorkers::run(std::size_t n, const std::function<void(std::size_t)>& task) {
  if (n == 0) return;
  if (n > 1) startThreads(n - 1);
  {
    std::lock_guard lock(mutex_);
    task_ = &task;
    children_ = n;
    next_ = 0;
    woken_ = 0;
    unfinished_.store(n);
  }
  drain(false);
  joinChildren();
}

void ChildWorkers::joinChildren() {
  std::size_t left = unfinished_.load();
  if (left == 0) return;
  aboutToBlock();  // runs around this one may have children waiting for this thread
  for (; left != 0; left = unfinished_.load()) unfinished_.wait(left);
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
    watch_.moved();
    if (next != nullptr) wake(*next);
    runTask(*task, index);
    if (unfinished_.fetch_sub(1) == 1) unfinished_.notify_one();
  }
}

void ChildWorkers::runTask(const std::function<void(std::size_t)>& task, std::size_t index) {
  const RunningRun run{.workers = this, .outer = running_run};
  running_run = &run;
  task(index);
  running_run = run.outer;
}

void ChildWorkers::aboutToBlock() {
  for (const RunningRun* run = running_run; run != nullptr; run = run->outer) {
    run->workers->wakeForUntaken();
  }
}

bool ChildWorkers::wakeForUntaken() {
  Worker* next = nullptr;
  {
    std::lock_guard lock(mutex_);
    if (next_ >= children_) return false;
    next = nextToWakeLocked();
  }
  if (next != nullptr) wake(*next);
  return true;
}

ChildWorkers::Worker* ChildWorkers::nextToWakeLocked() {
  if (woken_ >= workers_.size()) return nullptr;
  return &workers_[woken_++];
}

void ChildWorkers::wake(Worker& worker) {
  wakes_.fetch_add(1, std::memory_order_relaxed);
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
