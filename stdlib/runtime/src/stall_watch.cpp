// The watch's thread: a timed look per period while children are being taken, a sleep when
// nothing is left to watch (stall_watch.h).
#include "stall_watch.h"

namespace smachac::runtime {

void StallWatch::start() {
  if (thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    stop_ = false;
  }
  thread_ = std::thread([this] { loop(); });
}

void StallWatch::stop() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void StallWatch::loop() {
  std::unique_lock lock(mutex_);
  std::size_t seen = moves_.load();
  while (!stop_) {
    if (!asleep_.load()) {
      if (!watchOnePeriod(lock, seen)) sleepUnlessMoved(seen);
      continue;
    }
    wake_.wait(lock, [this] { return stop_ || !asleep_.load(); });
    seen = moves_.load();
  }
}

bool StallWatch::watchOnePeriod(std::unique_lock<std::mutex>& lock, std::size_t& seen) {
  if (wake_.wait_for(lock, kStallPeriod, [this] { return stop_; })) return true;
  std::size_t now = moves_.load();
  if (now != seen) {
    seen = now;
    return true;
  }
  lock.unlock();
  bool children_wait = stalled_();
  lock.lock();
  return children_wait;
}

// moved() increments moves_ and then reads asleep_; this sets asleep_ and then reads moves_.
// Both sequentially consistent, so at least one of them sees the other's write: either the
// watch stays awake or moved() wakes it.
void StallWatch::sleepUnlessMoved(std::size_t seen) {
  asleep_.store(true);
  if (moves_.load() != seen) asleep_.store(false);
}

void StallWatch::wakeUp() {
  {
    std::lock_guard lock(mutex_);
    asleep_.store(false);
  }
  wake_.notify_one();
}

}  // namespace smachac::runtime
