// SMACHA's generator, driven from the IR and shared by every code
// target: each state's template blocks are rendered in isolation into code buffers that flow
// up to the parent container; containers render with their children's code; the base template
// renders last with everything collected. A target supplies the template environment (its
// template sets, filters and tests), the blocks to skip, and what to do with the text.
//
// Kept from SMACHA: the 13 buffers and their insertion orders, level variables overriding a
// state's own keys, template globals persisting to later states at the same level and below,
// `defined_headers` shared by reference and pre-seeded by the base template, parent_type /
// parent_sm_name, and the leak of a sub-script call's params to later siblings.
// Fixed: an unknown template or a template error is a located error (the compile fails, every
// error is reported once), never a silently dropped state.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "backends/generator/template_catalog.h"
#include "backends/generator/template_values.h"
#include "backends/tmpl/environment.h"
#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"

namespace smachac::generator {

struct GeneratorContext {
  tmpl::Environment& env;
  ValueConverter& converter;  ///< the converter whose forced strings the env's tests know
  SourceManager& sources;
  DiagnosticEmitter& diags;
  TemplatePath path;                     ///< what `env` searches, for messages and suggestions
  std::vector<std::string> skip_blocks;  ///< blocks absent from every render
};

/// The base template's output, stripped, with one final newline; nullopt after errors.
std::optional<std::string> generate(const ir::Module& module, GeneratorContext& context);

/// The same, taking the module: it is freed once read, before the base render.
std::optional<std::string> generate(ir::Module&& module, GeneratorContext& context);

}  // namespace smachac::generator
