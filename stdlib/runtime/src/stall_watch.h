// StallWatch: a thread that notices when a Concurrence's children stop being taken, so that
// ChildWorkers wakes a worker only for a child that blocks or runs long (child_workers.h).
//
// The owner calls moved() each time a thread takes a child. While awake, the watch looks once
// every kStallPeriod; when no child was taken during a whole period it calls `stalled`, which
// wakes a worker if children wait to be taken and says whether any did. When none did, the
// watch sleeps until the next moved(), which wakes it (the only moved() that costs more than
// an atomic increment). So a busy Concurrence costs one timed wake-up of the watch per period,
// however many runs and children that period holds; an idle one costs nothing.
// Rules: `stalled` runs on the watch's thread with none of the watch's locks held; moved() may
// be called from any thread, before start() too.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>

namespace smachac::runtime {

class StallWatch {
 public:
  /// How long no child may be taken before the watch calls `stalled`: long enough that a
  /// thread switch per period costs little, short beside SMACH's start of a thread per child.
  static constexpr std::chrono::microseconds kStallPeriod{500};

  explicit StallWatch(std::function<bool()> stalled) : stalled_(std::move(stalled)) {}
  ~StallWatch() { stop(); }
  StallWatch(const StallWatch&) = delete;
  StallWatch& operator=(const StallWatch&) = delete;

  /// Starts the thread unless it runs; throws std::system_error when it cannot.
  void start();
  /// Stops and joins the thread (the destructor does it too).
  void stop();

  /// A child was taken.
  void moved() {
    moves_.fetch_add(1);  // sequentially consistent, like asleep_: see sleepUnlessMoved()
    if (asleep_.load()) wakeUp();
  }

 private:
  void loop();
  /// One period awake: calls `stalled` when nothing moved; false when the watch may sleep.
  bool watchOnePeriod(std::unique_lock<std::mutex>& lock, std::size_t& seen);
  /// Goes to sleep unless something moved after `seen`. Under mutex_.
  void sleepUnlessMoved(std::size_t seen);
  void wakeUp();

  std::function<bool()> stalled_;
  std::atomic<std::size_t> moves_{0};  ///< children taken, over every run
  std::atomic<bool> asleep_{false};    ///< set and cleared under mutex_
  std::mutex mutex_;                   ///< guards stop_ and the sleeps
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace smachac::runtime
