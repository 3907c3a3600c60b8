// ThreadObserver: a Concurrence reports its split before any child starts, one return per
// child (also when a child throws), and its join; nested Concurrences add up. Also built with
// ThreadSanitizer (label tsan).
#include <doctest/doctest.h>

#include <latch>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "helpers.h"

namespace rt = smachac::runtime;
using rt::testing::returns;

namespace {

// Counts the threads of the machine the way a lockstep simulator would.
class CountingObserver : public rt::ThreadObserver {
 public:
  void split(std::size_t children) override {
    std::lock_guard lock(mutex_);
    running_ += static_cast<int>(children) - 1;
    peak_ = std::max(peak_, running_);
    events_.push_back("split " + std::to_string(children));
  }
  void returned() override {
    std::lock_guard lock(mutex_);
    --running_;
    ++returns_;
  }
  void joined() override {
    std::lock_guard lock(mutex_);
    ++running_;
    events_.push_back("joined");
  }
  int running() const {
    std::lock_guard lock(mutex_);
    return running_;
  }
  int peak() const {
    std::lock_guard lock(mutex_);
    return peak_;
  }
  int returns() const {
    std::lock_guard lock(mutex_);
    return returns_;
  }
  std::vector<std::string> events() const {
    std::lock_guard lock(mutex_);
    return events_;
  }

 private:
  mutable std::mutex mutex_;
  int running_ = 1;
  int peak_ = 1;
  int returns_ = 0;
  std::vector<std::string> events_;
};

rt::ConcurrenceSpec allDone(rt::Keys children) {
  rt::OutcomeMap::mapped_type need;
  for (const std::string& child : children) need[child] = "done";
  return {.outcomes = {"done", "aborted"},
          .default_outcome = "aborted",
          .outcome_map = {{"done", need}}};
}

// A child that records how many threads the observer counts when it starts, then waits until
// every child has started (so none has returned while another records).
std::unique_ptr<rt::LambdaState> recordsRunning(const CountingObserver& observer,
                                                std::latch& started, int& seen) {
  return std::make_unique<rt::LambdaState>(rt::StateSpec{.outcomes = {"done"}},
                                           [&observer, &started, &seen](rt::UserData&) {
                                             seen = observer.running();
                                             started.arrive_and_wait();
                                             return std::string("done");
                                           });
}

}  // namespace

TEST_CASE("a Concurrence reports its split before any child starts, then returns and join") {
  CountingObserver observer;
  std::latch started(3);
  int seen_a = 0;
  int seen_b = 0;
  int seen_c = 0;
  rt::Concurrence con(allDone({"A", "B", "C"}));
  con.add("A", recordsRunning(observer, started, seen_a));
  con.add("B", recordsRunning(observer, started, seen_b));
  con.setThreadObserver(&observer);
  con.add("C", recordsRunning(observer, started, seen_c));  // added after: still observed
  CHECK(rt::run(con).outcome == "done");
  // Every child, even the first to start, already counts all three threads.
  CHECK(seen_a == 3);
  CHECK(seen_b == 3);
  CHECK(seen_c == 3);
  CHECK(observer.peak() == 3);
  CHECK(observer.returns() == 3);
  CHECK(observer.running() == 1);
  CHECK(observer.events() == std::vector<std::string>{"split 3", "joined"});
}

TEST_CASE("nested Concurrences inside a StateMachine add their threads up") {
  CountingObserver observer;
  rt::StateMachine sm({.outcomes = {"finished", "failed"}});
  auto inner = std::make_unique<rt::Concurrence>(allDone({"X", "Y"}));
  inner->add("X", returns("done"));
  inner->add("Y", returns("done"));
  auto outer = std::make_unique<rt::Concurrence>(allDone({"INNER", "Z"}));
  outer->add("INNER", std::move(inner));
  outer->add("Z", returns("done"));
  sm.add("OUTER", std::move(outer), {{"done", "finished"}, {"aborted", "failed"}});
  sm.setThreadObserver(&observer);
  CHECK(rt::run(sm).outcome == "finished");
  CHECK(observer.returns() == 4);
  CHECK(observer.running() == 1);
  CHECK(observer.peak() <= 3);
  const std::vector<std::string> events = observer.events();
  REQUIRE(events.size() == 4);
  CHECK(events.front() == "split 2");
  CHECK(events.back() == "joined");
}

TEST_CASE("a child that throws is counted as returned") {
  CountingObserver observer;
  rt::Concurrence con(allDone({"A", "B"}));
  con.add("A", returns("done"));
  con.add("B", std::make_unique<rt::LambdaState>(
                   rt::StateSpec{.outcomes = {"done"}},
                   [](rt::UserData&) -> std::string { throw std::runtime_error("boom"); }));
  con.setThreadObserver(&observer);
  CHECK_FALSE(rt::run(con).ok());
  CHECK(observer.returns() == 2);
  CHECK(observer.running() == 1);
}
