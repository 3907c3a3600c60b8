// Benchmarks of the C++ runtime (stdlib/runtime):
//   Transitions          a two-state StateMachine looping 100k times (items = transitions);
//                        the target is >= 1,000,000 transitions/s on one core
//   TransitionsUserdata  the same, each state reading and writing an int key
//   TransitionsTraced    the same as Transitions with a trace sink that only counts events
//   ConcurrenceFanOut/N  one execution of a Concurrence of N trivial children
//   NestedFanOut/N       a StateMachine running a Concurrence of N two-state machines
// Run: bench_runtime [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <atomic>
#include <memory>
#include <string>

#include "smachac/runtime/runtime.h"

namespace {

namespace rt = smachac::runtime;

constexpr int64_t kLoop = 100'000;

/// PING <-> PONG until `left` runs out; no userdata.
std::unique_ptr<rt::StateMachine> pingPong(int64_t& left) {
  auto sm = std::make_unique<rt::StateMachine>(rt::StateMachineSpec{.outcomes = {"done"}});
  auto body = [&left](rt::UserData&) { return --left > 0 ? "next" : "done"; };
  sm->add("PING",
          std::make_unique<rt::LambdaState>(rt::StateSpec{.outcomes = {"next", "done"}}, body),
          {{"next", "PONG"}});
  sm->add("PONG",
          std::make_unique<rt::LambdaState>(rt::StateSpec{.outcomes = {"next", "done"}}, body),
          {{"next", "PING"}});
  return sm;
}

/// PING <-> PONG counting in userdata key `n` (remapped for PONG) up to kLoop.
std::unique_ptr<rt::StateMachine> countingPingPong() {
  auto sm = std::make_unique<rt::StateMachine>(
      rt::StateMachineSpec{.outcomes = {"done"}, .userdata = {{"n", 0}}});
  auto body = [](rt::UserData& ud) {
    int64_t n = ud.get<int64_t>("i") + 1;
    ud.set("i", n);
    return n < kLoop ? "next" : "done";
  };
  rt::StateSpec spec{.outcomes = {"next", "done"}, .input_keys = {"i"}, .output_keys = {"i"}};
  sm->add("PING", std::make_unique<rt::LambdaState>(spec, body), {{"next", "PONG"}}, {{"i", "n"}});
  sm->add("PONG", std::make_unique<rt::LambdaState>(spec, body), {{"next", "PING"}}, {{"i", "n"}});
  return sm;
}

class CountingSink : public rt::TraceSink {
 public:
  void write(const rt::TraceEvent&) override { events.fetch_add(1, std::memory_order_relaxed); }
  std::atomic<int64_t> events{0};
};

void Transitions(benchmark::State& state) {
  int64_t left = 0;
  auto sm = pingPong(left);
  for (auto _ : state) {
    left = kLoop;
    benchmark::DoNotOptimize(rt::run(*sm).outcome);
  }
  state.SetItemsProcessed(state.iterations() * kLoop);
}
BENCHMARK(Transitions)->Unit(benchmark::kMillisecond);

void TransitionsUserdata(benchmark::State& state) {
  auto sm = countingPingPong();
  for (auto _ : state) {
    sm->userdata().set("n", 0);
    benchmark::DoNotOptimize(rt::run(*sm).outcome);
  }
  state.SetItemsProcessed(state.iterations() * kLoop);
}
BENCHMARK(TransitionsUserdata)->Unit(benchmark::kMillisecond);

void TransitionsTraced(benchmark::State& state) {
  int64_t left = 0;
  auto sm = pingPong(left);
  auto sink = std::make_shared<CountingSink>();
  sm->setTraceSink(sink);
  for (auto _ : state) {
    left = kLoop;
    benchmark::DoNotOptimize(rt::run(*sm).outcome);
  }
  state.SetItemsProcessed(state.iterations() * kLoop);
  state.counters["events/transition"] =
      static_cast<double>(sink->events.load()) / static_cast<double>(state.iterations() * kLoop);
}
BENCHMARK(TransitionsTraced)->Unit(benchmark::kMillisecond);

std::unique_ptr<rt::Concurrence> fanOut(int children) {
  auto con = std::make_unique<rt::Concurrence>(
      rt::ConcurrenceSpec{.outcomes = {"done"}, .default_outcome = "done", .outcome_map = {}});
  for (int i = 0; i < children; ++i) {
    con->add("C" + std::to_string(i),
             std::make_unique<rt::LambdaState>(rt::StateSpec{.outcomes = {"ok"}},
                                               [](rt::UserData&) { return "ok"; }));
  }
  return con;
}

void ConcurrenceFanOut(benchmark::State& state) {
  auto con = fanOut(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(rt::run(*con).outcome);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(ConcurrenceFanOut)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->UseRealTime();

void NestedFanOut(benchmark::State& state) {
  rt::StateMachine root({.outcomes = {"done"}});
  auto& con = root.add("PAR", std::make_unique<rt::Concurrence>(rt::ConcurrenceSpec{
                                  .outcomes = {"done"}, .default_outcome = "done"}));
  for (int64_t i = 0; i < state.range(0); ++i) {
    auto& sm =
        con.add("SM" + std::to_string(i),
                std::make_unique<rt::StateMachine>(rt::StateMachineSpec{.outcomes = {"ok"}}));
    sm.add("A",
           std::make_unique<rt::LambdaState>(rt::StateSpec{.outcomes = {"next"}},
                                             [](rt::UserData&) { return "next"; }),
           {{"next", "B"}});
    sm.add("B", std::make_unique<rt::LambdaState>(rt::StateSpec{.outcomes = {"ok"}},
                                                  [](rt::UserData&) { return "ok"; }));
  }
  for (auto _ : state) benchmark::DoNotOptimize(rt::run(root).outcome);
}
BENCHMARK(NestedFanOut)->Arg(2)->Arg(8)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
