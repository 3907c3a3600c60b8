// libFuzzer harness: bytes → YAML → IR → every pass → both IR printers. Any crash, hang,
// sanitizer report or failed SMACHAC_CHECK is a bug; diagnostics are the expected outcome
// for bad input.
#include <cstddef>
#include <cstdint>
#include <string>

#include "frontend/lower.h"
#include "ir/json.h"
#include "ir/printer.h"
#include "ir/support/diagnostic_printer.h"
#include "passes/pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smachac::SourceManager sources;
  smachac::DiagnosticEmitter diags;
  std::string text(reinterpret_cast<const char*>(data), size);
  auto module = smachac::frontend::lowerScriptText("fuzz.yml", std::move(text), {}, sources, diags);
  if (module) {
    smachac::passes::PassContext context{sources, diags, "smach"};
    smachac::passes::runPipeline(*module, context, {});
    smachac::ir::printModule(*module, sources);
    smachac::ir::moduleToJson(*module, sources);
  }
  for (const smachac::Diagnostic& d : diags.diagnostics()) {
    smachac::formatDiagnosticText(d, sources);
  }
  return 0;
}
