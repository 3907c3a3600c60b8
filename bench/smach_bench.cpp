// Benchmarks of the SMACH target (-target=smach): SMACHA's generator over the built-in
// templates.
//   smach/example/<name>   the whole in-process compile of an examples/core script: frontend,
//                          passes, generator (target: < 5 ms)
//   smach/generate/<N>     the generator alone on a generated script of N states (lowered and
//                          checked once, outside the timing): containers of 50 leaves, every
//                          tenth a Concurrence, leaves with userdata, every fifth a lambda
//                          callback (targets: 100k states < 2 s and < 500 MB, linear)
// Counters: states/s; the process's peak RSS in MB after the run; for generate, the RSS before
// the first generation (the lowered script) and the peak growth during generation.
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include <string>
#include <utility>

#include "backends/smach/smach_target.h"
#include "frontend/lower.h"
#include "passes/pipeline.h"

namespace {

using smachac::DiagnosticEmitter;
using smachac::SourceManager;

double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// The current resident set size in MB (from /proc/self/statm).
double currentRssMb() {
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(f);
  }
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1048576.0;
}

std::string leaf(const std::string& name, int j, const std::string& next, bool concurrent) {
  std::string s = "        - " + name + ":\n";
  if (j % 5 == 4) {
    s += "            template: CallbacksState\n            input_keys: [speed]\n"
         "            output_keys: [speed]\n"
         "            callbacks: {speed: '`lambda ud: ud.speed * 1.01`'}\n";
  } else {
    s += "            template: PrintUserdataState\n            input_keys: [speed]\n"
         "            userdata: {note_" +
         std::to_string(j) + ": step " + std::to_string(j) + "}\n";
  }
  if (!concurrent) s += "            transitions: {succeeded: " + next + "}\n";
  return s;
}

std::string container(int c, int leaves, const std::string& next) {
  bool concurrent = c % 10 == 9;
  std::string name = "C" + std::to_string(c);
  std::string s = "  - " + name +
                  ":\n      template: " + (concurrent ? "Concurrence" : "StateMachine") +
                  "\n      outcomes: [ok]\n      input_keys: [speed]\n";
  if (concurrent) {
    s += "      default_outcome: ok\n      outcome_map: {ok: {" + name + "_0: succeeded}}\n";
  }
  s += "      transitions: {ok: " + next + "}\n      states:\n";
  for (int j = 0; j < leaves; ++j) {
    std::string succ = j + 1 < leaves ? name + "_" + std::to_string(j + 1) : "ok";
    s += leaf(name + "_" + std::to_string(j), j, succ, concurrent);
  }
  return s;
}

/// A script of about `states` states (containers included).
std::string scaleScript(int states) {
  constexpr int kLeaves = 50;
  int containers = std::max(1, states / (kLeaves + 1));
  std::string s =
      "name: scale\ntemplate: Base\noutcomes: [done]\nuserdata: {speed: 0.5}\n"
      "states:\n";
  for (int c = 0; c < containers; ++c) {
    s += container(c, kLeaves, c + 1 < containers ? "C" + std::to_string(c + 1) : "done");
  }
  return s;
}

struct Compiled {
  SourceManager sources;
  DiagnosticEmitter diags;
  std::optional<smachac::ir::Module> module;
};

void compile(Compiled& c, const std::string& path, const std::string* text) {
  c.module = text ? smachac::frontend::lowerScriptText(path, *text, {}, c.sources, c.diags)
                  : smachac::frontend::lowerScript(path, {}, c.sources, c.diags);
  if (!c.module) return;
  smachac::passes::PassContext context{c.sources, c.diags, "smach"};
  if (!smachac::passes::runPipeline(*c.module, context, {})) c.module.reset();
}

/// Emits a copy of the module (the target takes the module it is given).
bool emit(Compiled& c, smachac::ir::Module module) {
  smachac::backends::EmitOptions options;
  smachac::backends::EmitContext context{c.sources, c.diags, options};
  return smachac::backends::smach::emitSmach(std::move(module), context).has_value();
}

void example(benchmark::State& state, const std::string& path) {
  for (auto _ : state) {
    Compiled c;
    compile(c, path, nullptr);
    if (!c.module || !emit(c, std::move(*c.module))) {
      state.SkipWithError(("cannot compile " + path).c_str());
      break;
    }
  }
  state.counters["peak_rss_MB"] = peakRssMb();
}

void generate(benchmark::State& state) {
  std::string text = scaleScript(static_cast<int>(state.range(0)));
  Compiled c;
  compile(c, "scale.yml", &text);
  if (!c.module) return state.SkipWithError("the scale script does not compile");
  double before = currentRssMb();
  double peak_growth = 0;
  for (auto _ : state) {
    state.PauseTiming();
    smachac::ir::Module copy = *c.module;
    state.ResumeTiming();
    if (!emit(c, std::move(copy))) {
      state.SkipWithError("generation failed");
      break;
    }
    peak_growth = std::max(peak_growth, peakRssMb() - before);
  }
  state.counters["states_per_s"] =
      benchmark::Counter(static_cast<double>(c.module->stateCount()) * state.iterations(),
                         benchmark::Counter::kIsRate);
  state.counters["peak_rss_MB"] = peakRssMb();
  state.counters["rss_before_MB"] = before;
  state.counters["generator_peak_MB"] = peak_growth;
  state.SetComplexityN(static_cast<int64_t>(c.module->stateCount()));
}

void registerExamples() {
  for (const char* name : {"sequence", "nesting", "concurrence", "shorthand", "sub_scripts"}) {
    std::string path = std::string(SMACHAC_BENCH_EXAMPLES) + "/" + name + ".yml";
    benchmark::RegisterBenchmark(("smach/example/" + std::string(name)).c_str(), example, path)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

BENCHMARK(generate)
    ->Name("smach/generate")
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity();

int main(int argc, char** argv) {
  registerExamples();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
