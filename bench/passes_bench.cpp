// Benchmarks of the whole front half of the compiler (frontend + every pass) and of the passes
// alone, on generated scripts of 1k, 10k and 100k states. Two shapes:
//   nested  the root runs a sequence of StateMachine containers of 50 leaves each, every
//           tenth container a Concurrence of 4 leaves; leaves read and write keys from a small
//           vocabulary and have retry loops (back edges)
//   flat    one container of N leaves in a chain with back edges: the worst case for the
//           per-container graph and dataflow analyses
//   unique  like flat, but every state writes a key of its own that the next one reads: N
//           distinct keys in one scope (settled by dominance, not by the bit-set solver)
// Both are clean scripts (no diagnostics), so every pass does its full work. Run:
//   smachac_passes_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "frontend/lower.h"
#include "passes/pipeline.h"

namespace {

namespace fs = std::filesystem;

constexpr int kKeys = 8;  // the key vocabulary: k0 .. k7
constexpr int kPerContainer = 50;

std::string key(int i) { return "k" + std::to_string(i % kKeys); }

/// A leaf that reads the previous key and writes the next; `next`/`back` are its targets.
std::string leaf(const std::string& indent, const std::string& name, int j, const std::string& next,
                 const std::string& back) {
  return indent + "- " + name + ":\n" + indent + "    template: WorkState\n" + indent +
         "    outcomes: [succeeded, aborted]\n" + indent + "    input_keys: [speed, " +
         key(j + kKeys - 1) + "]\n" + indent + "    output_keys: [" + key(j) + "]\n" + indent +
         "    transitions: {succeeded: " + next + ", aborted: " + back + "}\n";
}

std::string header(int keys_defined_by_root) {
  std::string s = "name: scale\ntemplate: Base\noutcomes: [done, failed]\nuserdata: {speed: 0.5";
  for (int k = 0; k < keys_defined_by_root; ++k) s += ", " + key(k) + ": 0";
  return s + "}\nstates:\n";
}

std::string stateMachine(int c, int states, const std::string& next) {
  std::string name = "C" + std::to_string(c);
  std::string s = "  - " + name +
                  ":\n      template: StateMachine\n      outcomes: [ok, failed]\n"
                  "      input_keys: [speed, " +
                  key(kKeys - 1) +
                  "]\n"
                  "      output_keys: [" +
                  key(states - 1) +
                  "]\n"
                  "      transitions: {ok: " +
                  next + ", failed: failed}\n      states:\n";
  for (int j = 0; j < states; ++j) {
    std::string self = name + "_" + std::to_string(j);
    std::string succ = j + 1 < states ? name + "_" + std::to_string(j + 1) : "ok";
    std::string back = j > 0 ? name + "_" + std::to_string(j - 1) : "failed";
    s += leaf("        ", self, j, succ, back);
  }
  return s;
}

std::string concurrence(int c, const std::string& next) {
  std::string name = "C" + std::to_string(c);
  std::string s = "  - " + name +
                  ":\n      template: Concurrence\n      outcomes: [ok, failed]\n"
                  "      default_outcome: failed\n      input_keys: [speed]\n"
                  "      outcome_map: {ok: {" +
                  name + "_0: succeeded, " + name +
                  "_1: succeeded}}\n      transitions: {ok: " + next +
                  ", failed: failed}\n"
                  "      states:\n";
  for (int j = 0; j < 4; ++j) {
    s += "        - " + name + "_" + std::to_string(j) +
         ":\n            template: WorkState\n            outcomes: [succeeded, aborted]\n"
         "            input_keys: [speed]\n            output_keys: [out" +
         std::to_string(j) + "]\n";
  }
  return s;
}

std::string nestedScript(int states) {
  std::string s = header(kKeys);
  int containers = std::max(1, states / kPerContainer);
  for (int c = 0; c < containers; ++c) {
    std::string next = c + 1 < containers ? "C" + std::to_string(c + 1) : "done";
    s += c % 10 == 9 ? concurrence(c, next) : stateMachine(c, kPerContainer, next);
  }
  return s;
}

std::string flatScript(int states) {
  std::string s = header(kKeys);
  for (int j = 0; j < states; ++j) {
    std::string succ = j + 1 < states ? "S" + std::to_string(j + 1) : "done";
    std::string back = j > 0 ? "S" + std::to_string(j - 1) : "failed";
    s += leaf("  ", "S" + std::to_string(j), j, succ, back);
  }
  return s;
}

std::string uniqueKeysScript(int states) {
  std::string s = "name: scale\ntemplate: Base\noutcomes: [done, failed]\nstates:\n";
  for (int j = 0; j < states; ++j) {
    std::string id = std::to_string(j);
    std::string succ = j + 1 < states ? "S" + std::to_string(j + 1) : "done";
    std::string back = j > 0 ? "S" + std::to_string(j - 1) : "failed";
    std::string reads = j > 0 ? "u" + std::to_string(j - 1) : "";
    s += "  - S" + id + ": {template: WorkState, outcomes: [succeeded, aborted], input_keys: [" +
         reads + "], output_keys: [u" + id + "], transitions: {succeeded: " + succ +
         ", aborted: " + back + "}}\n";
  }
  return s;
}

fs::path writeScript(const std::string& text, const std::string& tag) {
  fs::path path = fs::temp_directory_path() /
                  ("smachac_bench_" + tag + "_" + std::to_string(::getpid()) + ".yml");
  std::ofstream(path) << text;
  return path;
}

/// Lowers and checks `path`; aborts the benchmark if the script is not clean.
std::optional<smachac::ir::Module> compile(const fs::path& path, bool run_passes,
                                           benchmark::State& state) {
  smachac::SourceManager sources;
  smachac::DiagnosticEmitter diags;
  auto module = smachac::frontend::lowerScript(path.string(), {}, sources, diags);
  if (module && run_passes) {
    smachac::passes::PassContext context{sources, diags, "smach"};
    smachac::passes::runPipeline(*module, context, {});
  }
  if (!module || !diags.diagnostics().empty()) state.SkipWithError("the script is not clean");
  return module;
}

template <std::string (*Generate)(int)>
void pipeline(benchmark::State& state) {
  fs::path path = writeScript(Generate(static_cast<int>(state.range(0))), "pipeline");
  for (auto _ : state) benchmark::DoNotOptimize(compile(path, true, state));
  fs::remove(path);
  state.SetComplexityN(state.range(0));
}

template <std::string (*Generate)(int)>
void passesOnly(benchmark::State& state) {
  fs::path path = writeScript(Generate(static_cast<int>(state.range(0))), "passes");
  std::optional<smachac::ir::Module> lowered = compile(path, false, state);
  fs::remove(path);
  for (auto _ : state) {
    state.PauseTiming();
    smachac::ir::Module module = *lowered;
    smachac::SourceManager sources;
    smachac::DiagnosticEmitter diags;
    smachac::passes::PassContext context{sources, diags, "smach"};
    state.ResumeTiming();
    smachac::passes::runPipeline(module, context, {});
  }
  state.SetComplexityN(state.range(0));
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->Complexity();
}

BENCHMARK(pipeline<nestedScript>)->Name("pipeline/nested")->Apply(sizes);
BENCHMARK(pipeline<flatScript>)->Name("pipeline/flat")->Apply(sizes);
BENCHMARK(passesOnly<nestedScript>)->Name("passes/nested")->Apply(sizes);
BENCHMARK(passesOnly<flatScript>)->Name("passes/flat")->Apply(sizes);
BENCHMARK(passesOnly<uniqueKeysScript>)->Name("passes/unique")->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
