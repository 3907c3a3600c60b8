// The threads a Concurrence runs its children on, started at its first execution and kept for
// the next ones (SMACH starts a thread per child per execution).
//
// Children are taken in order, each by one thread: the calling thread takes child 0, then the
// next child nobody has taken, and so on, waking nobody. A worker is woken only when a child
// blocks or runs long: at once when the child's thread is about to block where the runtime
// sees it (aboutToBlock(): State::waitForPreempt, SleepState, a nested Concurrence waiting for
// its children), otherwise when no child was taken for StallWatch::kStallPeriod while others
// wait (stall_watch.h). A woken worker takes children the same way and, while others are left
// untaken, wakes the next worker: once one child blocked, the rest spread over the threads.
// So children that return quickly run one after another on the calling thread without a
// thread switch (which costs more than such a child), while a child that blocks never keeps
// another from starting for longer than a stall period: there are as many threads as
// children, and a stall always wakes one more. run() returns when every child has returned.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <thread>

#include "smachac/runtime/light_mutex.h"
#include "stall_watch.h"

namespace smachac::runtime {

class ChildWorkers {
 public:
  ChildWorkers() : watch_([this] { return wakeForUntaken(); }) {}
  ~ChildWorkers();
  ChildWorkers(const ChildWorkers&) = delete;
  ChildWorkers& operator=(const ChildWorkers&) = delete;

  /// Runs task(0) ... task(n - 1), each once, at the same time as far as they block; `task`
  /// must not throw. Throws std::system_error, before any task runs, when a thread cannot be
  /// started.
  void run(std::size_t n, const std::function<void(std::size_t)>& task);

  /// Workers woken so far, over every run (tests check that quick children wake none).
  std::size_t wakes() const { return wakes_.load(std::memory_order_relaxed); }

  /// The calling thread is about to block: for each run it is running a child of, innermost
  /// first, wakes a worker when children of that run wait to be taken.
  static void aboutToBlock();

 private:
  struct Worker {
    std::atomic<uint32_t> wakes{0};  ///< bumped to wake it
    std::thread thread;
  };

  void startThreads(std::size_t workers);
  /// Takes and runs children until none is left; `wake_next`: wake a worker when one is.
  void drain(bool wake_next);
  /// Runs child `index` with this run noted as the thread's innermost (for aboutToBlock()).
  void runTask(const std::function<void(std::size_t)>& task, std::size_t index);
  /// Wakes a worker when children wait to be taken; returns whether any do.
  bool wakeForUntaken();
  /// The worker to wake next in this run, or null when every one was woken. Under mutex_.
  Worker* nextToWakeLocked();
  void wake(Worker& worker);
  void work(Worker& self);
  void joinChildren();

  LightMutex mutex_;  ///< guards task_, children_, next_, woken_
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t children_ = 0;  ///< of the current run
  std::size_t next_ = 0;      ///< the next child to take
  std::size_t woken_ = 0;     ///< workers woken in the current run
  std::atomic<std::size_t> unfinished_{0};
  std::atomic<std::size_t> wakes_{0};
  std::atomic<bool> stop_{false};
  std::deque<Worker> workers_;  ///< a deque: workers never move
  StallWatch watch_;            ///< calls wakeForUntaken(); stopped before the workers
};

}  // namespace smachac::runtime
