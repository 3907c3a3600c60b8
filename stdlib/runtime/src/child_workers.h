// The threads a Concurrence runs its children on, started at its first execution and kept for
// the next ones (SMACH starts a thread per child per execution).
//
// Children are taken in order, each by one thread: the calling thread takes child 0, then the
// next child nobody has taken, and so on; the workers take children the same way. A run wakes
// one worker, and a worker that takes a child while others still wait to be taken wakes the
// next worker. So children that return quickly run one after another on the calling thread
// without a thread switch (which costs more than such a child), while a child that blocks
// never keeps another from starting: every child not yet taken has a worker on its way to it.
// run() returns when every child has returned.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <thread>

#include "smachac/runtime/light_mutex.h"

namespace smachac::runtime {

class ChildWorkers {
 public:
  ChildWorkers() = default;
  ~ChildWorkers();
  ChildWorkers(const ChildWorkers&) = delete;
  ChildWorkers& operator=(const ChildWorkers&) = delete;

  /// Runs task(0) ... task(n - 1), each once, at the same time as far as they block; `task`
  /// must not throw. Throws std::system_error, before any task runs, when a worker cannot be
  /// started.
  void run(std::size_t n, const std::function<void(std::size_t)>& task);

 private:
  struct Worker {
    std::atomic<uint32_t> wakes{0};  ///< bumped to wake it
    std::thread thread;
  };

  void startWorkers(std::size_t count);
  /// Takes and runs children until none is left; `wake_next`: wake a worker when one is.
  void drain(bool wake_next);
  /// The worker to wake next in this run, or null when every one was woken. Under mutex_.
  Worker* nextToWakeLocked();
  static void wake(Worker& worker);
  void work(Worker& self);

  LightMutex mutex_;  ///< guards task_, children_, next_, woken_
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t children_ = 0;  ///< of the current run
  std::size_t next_ = 0;      ///< the next child to take
  std::size_t woken_ = 0;     ///< workers woken in the current run
  std::atomic<std::size_t> unfinished_{0};
  std::atomic<bool> stop_{false};
  std::deque<Worker> workers_;  ///< a deque: workers never move
};

}  // namespace smachac::runtime
