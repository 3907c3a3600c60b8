// LightMutex: mutual exclusion under contention, with threads sleeping on it.
#include <doctest/doctest.h>

#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "smachac/runtime/light_mutex.h"

namespace rt = smachac::runtime;

TEST_CASE("LightMutex excludes: every increment of several threads counts") {
  rt::LightMutex mutex;
  int64_t counter = 0;  // guarded by mutex; TSan reports a race if it is not
  constexpr int kThreads = 8;
  constexpr int kIncrements = 20000;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < kIncrements; ++i) {
        std::lock_guard lock(mutex);
        ++counter;
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  CHECK(counter == int64_t{kThreads} * kIncrements);
}

TEST_CASE("LightMutex try_lock fails while it is held") {
  rt::LightMutex mutex;
  REQUIRE(mutex.try_lock());
  bool other = true;
  std::thread([&] { other = mutex.try_lock(); }).join();
  CHECK_FALSE(other);
  mutex.unlock();
  CHECK(mutex.try_lock());
  mutex.unlock();
}
