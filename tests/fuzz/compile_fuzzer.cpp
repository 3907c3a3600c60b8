// libFuzzer harness for the whole compile: bytes → script → frontend, then for each target
// (ir, json, smach, dot, flexbe, cpp) on a copy of the module: passes → template and code
// checks → emit, in memory, as the driver does it (nothing is written). Every second target
// also runs the optimisation passes. Any crash, hang, leak, sanitizer report or failed
// SMACHAC_CHECK is a bug; diagnostics are the expected outcome for bad input, and they are
// printed in every format.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>

#include "backends/meta/template_check.h"
#include "backends/target_code_check.h"
#include "backends/targets.h"
#include "frontend/lower.h"
#include "ir/support/diagnostic_printer.h"
#include "passes/pipeline.h"

namespace {

using namespace smachac;

void printEveryFormat(const DiagnosticEmitter& diags, const SourceManager& sources) {
  for (DiagnosticFormat format :
       {DiagnosticFormat::Text, DiagnosticFormat::Json, DiagnosticFormat::Sarif}) {
    std::ostringstream out;
    printDiagnostics(out, diags.diagnostics(), sources, format);
  }
}

/// Passes, template and code checks and emit for one target, on a copy of the lowered module.
void compileTo(const backends::Target& target, ir::Module module, SourceManager& sources,
               bool optimize) {
  DiagnosticEmitter diags;
  passes::PassContext context{sources, diags, std::string(target.name)};
  passes::PipelineOptions pipeline;
  pipeline.optimize = optimize;
  bool passes_ok = passes::runPipeline(module, context, pipeline);
  bool templates_ok = backends::checkTemplates(module, target.name, {}, diags);
  bool code_ok = backends::checkTargetCode(module, target.name, diags);
  if (passes_ok && templates_ok && code_ok) {
    backends::EmitOptions options;
    backends::EmitContext emit{sources, diags, options};
    target.emit(std::move(module), emit);
  }
  printEveryFormat(diags, sources);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  SourceManager sources;
  DiagnosticEmitter diags;
  std::string text(reinterpret_cast<const char*>(data), size);
  auto module = frontend::lowerScriptText("fuzz.yml", std::move(text), {}, sources, diags);
  printEveryFormat(diags, sources);
  if (!module) return 0;
  bool optimize = false;
  for (const backends::Target& target : backends::targets()) {
    compileTo(target, *module, sources, optimize);
    optimize = !optimize;
  }
  return 0;
}
