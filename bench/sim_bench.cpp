// Benchmarks of the MuJoCo Baxter simulation, headless: the real-time factor (simulated
// seconds per wall-clock second) of the paper's pick-and-place run, IK included (target >= 15
// on the project's 2-core machine), and of plain stepping with both arms holding still.
// The run is single-threaded, so CPU time measures it even when other jobs share the cores.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>

#include "smachac/sim/bodies.h"
#include "smachac/sim/ik.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/scripted_tasks.h"
#include "smachac/sim/standard_poses.h"
#include "smachac/sim/world.h"

namespace {

using smachac::sim::Side;
using smachac::sim::World;

std::unique_ptr<World> loadOrDie() {
  smachac::sim::LoadResult loaded = World::loadDefault();
  if (!loaded.world) {
    std::fprintf(stderr, "sim_bench: %s\n", loaded.error.c_str());
    std::exit(2);
  }
  return std::move(loaded.world);
}

smachac::sim::Pose overhead(double x, double y, double z) {
  return {{x, y, z}, smachac::sim::overheadOrientation()};
}

// One run of the pick-and-place experiment; returns false when a step fails.
bool pickAndPlace(World& world, smachac::sim::Ik& ik) {
  world.reset();
  smachac::sim::placeBody(world, "block1", {{0.7, 0.15, -0.13}, {}});
  if (!world.limb(Side::Left).moveToJointPositions(smachac::sim::untuckPose(Side::Left)).ok()) {
    return false;
  }
  return smachac::sim::pickBlock(world, ik, Side::Left, overhead(0.7, 0.15, -0.129)).ok &&
         smachac::sim::placeBlock(world, ik, Side::Left, overhead(0.75, 0.0, -0.129)).ok;
}

void BM_SimPickAndPlace(benchmark::State& state) {
  auto world = loadOrDie();
  smachac::sim::Ik ik(*world);
  double simulated = 0.0;
  double wall = 0.0;
  double cpu = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    if (!pickAndPlace(*world, ik)) state.SkipWithError("pick and place failed");
    cpu += static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    simulated += world->time();
  }
  // Wall-clock factor, and the factor on this process's CPU time (what a busy machine hides).
  state.counters["real_time_factor"] = simulated / wall;
  state.counters["cpu_real_time_factor"] = simulated / cpu;
  state.counters["sim_seconds"] = simulated / static_cast<double>(state.iterations());
}
BENCHMARK(BM_SimPickAndPlace)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_SimStepIdle(benchmark::State& state) {
  auto world = loadOrDie();
  constexpr int kSteps = 1000;
  for (auto _ : state) world->step(kSteps);
  state.counters["real_time_factor"] = world->realTimeFactor();
  state.counters["steps_per_second"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * kSteps, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimStepIdle)->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
