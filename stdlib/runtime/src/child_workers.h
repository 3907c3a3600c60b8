// The threads a Concurrence runs its children on, started at its first execution and kept
// for the next ones: a Concurrence in a loop starts no thread per child per execution (SMACH
// does; it was most of the time of a fan-out). Child 0 runs on the calling thread, child i on
// worker i; run() returns when every child has returned.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace smachac::runtime {

class ChildWorkers {
 public:
  ChildWorkers() = default;
  ~ChildWorkers();
  ChildWorkers(const ChildWorkers&) = delete;
  ChildWorkers& operator=(const ChildWorkers&) = delete;

  /// Runs task(0) here and task(1) ... task(n - 1) on the workers, at the same time; `task`
  /// must not throw. Throws std::system_error, before any task runs, when a worker cannot be
  /// started.
  void run(std::size_t n, const std::function<void(std::size_t)>& task);

 private:
  void work(std::size_t index, uint64_t seen);

  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  std::vector<std::thread> threads_;
  const std::function<void(std::size_t)>* task_ = nullptr;
  uint64_t generation_ = 0;   ///< one per run()
  std::size_t children_ = 0;  ///< of the current run()
  std::size_t pending_ = 0;   ///< workers of the current run() still running
  bool stop_ = false;
};

}  // namespace smachac::runtime
