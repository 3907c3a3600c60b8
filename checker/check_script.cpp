// The check pipeline of one script.
#include "checker/check_script.h"

#include "backends/expr/lower_expressions.h"
#include "backends/meta/template_check.h"
#include "backends/target_code_check.h"
#include "frontend/lower.h"
#include "ir/support/suggest.h"
#include "passes/pipeline.h"

namespace smachac::checker {
namespace {

std::optional<ir::Module> lower(const std::string& path, std::optional<std::string> text,
                                const frontend::FrontendOptions& options, SourceManager& sources,
                                DiagnosticEmitter& diags) {
  if (!text) return frontend::lowerScript(path, options, sources, diags);
  return frontend::lowerScriptText(path, std::move(*text), options, sources, diags);
}

/// Passes, expressions, templates and target code; false when one of them found an error.
bool checkModule(ir::Module& module, const CheckOptions& options, SourceManager& sources,
                 DiagnosticEmitter& diags) {
  passes::PassContext context{sources, diags, options.target};
  passes::PipelineOptions pipeline;
  pipeline.disabled.insert(options.disabled_passes.begin(), options.disabled_passes.end());
  pipeline.print_ir_after = options.print_ir_after;
  pipeline.optimize = options.optimize;
  pipeline.print_ir = options.print_ir;
  // The template and code checks run after failed graph checks too: their errors are
  // independent.
  bool passes_ok = passes::runPipeline(module, context, pipeline);
  backends::expr::lowerPortableExpressions(module, options.target);
  bool templates_ok =
      backends::checkTemplates(module, options.target, options.template_dirs, diags);
  bool code_ok = backends::checkTargetCode(module, options.target, diags);
  return passes_ok && templates_ok && code_ok;
}

}  // namespace

CheckedScript checkScript(const std::string& path, std::optional<std::string> text,
                          const CheckOptions& options, SourceManager& sources,
                          DiagnosticEmitter& diags) {
  size_t first = diags.diagnostics().size();
  size_t errors_before = diags.errorCount();
  SuggestionBudget suggestions;  // "did you mean" for as many names as 10 M comparisons allow
  CheckedScript checked;
  frontend::FrontendOptions frontend_options{options.script_dirs, &checked.include_sites,
                                             options.sub_script_alone, options.overlay,
                                             options.keep_module_on_error};
  checked.module = lower(path, std::move(text), frontend_options, sources, diags);
  if (checked.module && diags.errorCount() == errors_before) {
    checked.ok = checkModule(*checked.module, options, sources, diags);
  }
  frontend::noteInclusions(diags, first, checked.include_sites);
  if (!checked.ok && !options.keep_module_on_error) checked.module.reset();
  return checked;
}

}  // namespace smachac::checker
