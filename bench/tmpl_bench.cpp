// Benchmarks of the template engine: parse + render of a state template (macros, extends,
// include), a cached render, and the 1,000-state SMACHA-shaped workload (target < 50 ms).
#include <benchmark/benchmark.h>

#include "bench/tmpl_workload.h"

namespace {

using smachac::tmpl::Environment;
using smachac::tmpl::RenderOptions;
using smachac::tmpl::Value;

const std::vector<smachac::EmbeddedFile> kNoBuiltins;

std::unique_ptr<Environment> makeEnv() {
  return std::make_unique<Environment>(std::vector<std::string>{SMACHAC_BENCH_TEMPLATES},
                                       std::vector<std::string>{}, kNoBuiltins);
}

// One full render of the leaf state template (its base, macro library and helper included).
std::string renderState(Environment& env) {
  Value headers = Value::newList();
  return env.render("WorkState.tpl.py", smachac::bench::stateContext(1, 10, headers),
                    RenderOptions{{"meta"}});
}

void BM_TmplParseAndRender(benchmark::State& state) {
  for (auto _ : state) {
    auto env = makeEnv();
    benchmark::DoNotOptimize(renderState(*env));
  }
}
BENCHMARK(BM_TmplParseAndRender)->Unit(benchmark::kMicrosecond);

void BM_TmplRender(benchmark::State& state) {
  auto env = makeEnv();
  for (auto _ : state) benchmark::DoNotOptimize(renderState(*env));
}
BENCHMARK(BM_TmplRender)->Unit(benchmark::kMicrosecond);

void BM_TmplRenderBlock(benchmark::State& state) {
  auto env = makeEnv();
  Value headers = Value::newList();
  Value ctx = smachac::bench::stateContext(1, 10, headers);
  for (auto _ : state) {
    std::string out = env->renderBlock("WorkState.tpl.py", "body", ctx);
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_TmplRenderBlock)->Unit(benchmark::kMicrosecond);

void BM_TmplSmachaWorkload1000(benchmark::State& state) {
  auto env = makeEnv();
  smachac::bench::runSmachaWorkload(*env, 1000);  // warm the template cache
  for (auto _ : state) benchmark::DoNotOptimize(smachac::bench::runSmachaWorkload(*env, 1000));
}
BENCHMARK(BM_TmplSmachaWorkload1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
