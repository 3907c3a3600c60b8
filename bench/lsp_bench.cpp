// The language server's re-analysis after a one-character edit, on flat scripts of 100, 1,000
// and 10,000 states: the editor's change is applied to the open document, the document is
// analysed again (the whole check, as `smachac lint`) and its diagnostics are turned into the
// publishDiagnostics message. Each iteration flips one character of a key in the middle of
// the script, so the analyses alternate between a clean script and one with an error.
// The target: under 50 ms at 1,000 states. Run:
//   bench_lsp [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <string>

#include "lsp/features/diagnostics.h"
#include "lsp/workspace.h"

namespace {

using smachac::lsp::Json;

/// A chain of PrintUserdataStates that all read the root's `text`.
std::string flatScript(int states) {
  std::string s =
      "name: scale\ntemplate: Base\noutcomes: [done]\nuserdata: {text: hello}\nstates:\n";
  for (int j = 0; j < states; ++j) {
    std::string next = j + 1 < states ? "S" + std::to_string(j + 1) : "done";
    s += "  - S" + std::to_string(j) +
         ": {template: PrintUserdataState, input_keys: [text], transitions: {succeeded: " + next +
         "}}\n";
  }
  return s;
}

/// The change that replaces the character at `line`:`character` with `text`.
Json oneCharacterChange(uint32_t line, uint32_t character, const std::string& text) {
  Json range = {{"start", {{"line", line}, {"character", character}}},
                {"end", {{"line", line}, {"character", character + 1}}}};
  return Json::array({{{"range", range}, {"text", text}}});
}

void reanalysis(benchmark::State& state) {
  int states = static_cast<int>(state.range(0));
  std::string script = flatScript(states);
  smachac::lsp::Workspace workspace({});
  const std::string uri = "untitled:scale.yml";
  workspace.documents().open(uri, script, 1);
  workspace.opened(uri);
  if (!workspace.analysis(uri)->diagnostics.empty()) state.SkipWithError("not a clean script");
  // The last `t` of `[text]` in the middle state's line (the header is 5 lines).
  size_t line_start = script.find("  - S" + std::to_string(states / 2) + ": ");
  auto line = static_cast<uint32_t>(5 + states / 2);
  auto column = static_cast<uint32_t>(script.find("[text]", line_start) - line_start + 4);
  int64_t version = 1;
  for (auto _ : state) {
    std::string character = version % 2 == 1 ? "u" : "t";  // text → texu → text
    workspace.documents().change(uri, ++version, oneCharacterChange(line, column, character));
    workspace.changed(uri);
    benchmark::DoNotOptimize(
        smachac::lsp::publishDiagnosticsParams(*workspace.analysis(uri)).dump());
  }
  state.SetComplexityN(states);
}

BENCHMARK(reanalysis)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
