// LightMutex: the lock of what a running machine touches at every step (a userdata store, a
// state machine's current child). Uncontended, lock() and unlock() are one atomic operation
// each, where std::mutex goes through pthread_mutex_lock and _unlock (about ten times the
// instructions: a third of a counter loop's time). Contended, a thread sleeps in
// std::atomic::wait (a futex on Linux) instead of spinning: a three-state lock (free, locked,
// locked with sleepers), as in Drepper's "Futexes Are Tricky". Use it with std::lock_guard.
#pragma once

#include <atomic>

namespace smachac::runtime {

class LightMutex {
 public:
  LightMutex() = default;
  LightMutex(const LightMutex&) = delete;
  LightMutex& operator=(const LightMutex&) = delete;

  void lock() {
    int state = kFree;
    if (state_.compare_exchange_strong(state, kLocked, std::memory_order_acquire)) return;
    if (state != kSleepers) state = state_.exchange(kSleepers, std::memory_order_acquire);
    while (state != kFree) {
      state_.wait(kSleepers, std::memory_order_relaxed);
      state = state_.exchange(kSleepers, std::memory_order_acquire);
    }
  }

  // NOLINTNEXTLINE(readability-identifier-naming): the name std::unique_lock calls
  bool try_lock() {
    int state = kFree;
    return state_.compare_exchange_strong(state, kLocked, std::memory_order_acquire);
  }

  void unlock() {
    if (state_.exchange(kFree, std::memory_order_release) == kSleepers) state_.notify_one();
  }

 private:
  static constexpr int kFree = 0;
  static constexpr int kLocked = 1;    ///< no thread sleeps on it
  static constexpr int kSleepers = 2;  ///< a thread may sleep on it: unlock() wakes one

  std::atomic<int> state_{kFree};
};

}  // namespace smachac::runtime
