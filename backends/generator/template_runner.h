// SMACHA's templater operations on top of the template engine, with the caches SMACHA lacked:
// script-level template names are resolved once, block lists computed once per template.
//   renderBlocks  every block of a template rendered in isolation
//   exports       the template's module variables minus those its `local_vars` lists
//   renderBase    the whole base template, `meta` skipped, stripped
// Blocks in `skip_blocks` (comment and introspection blocks without -c/-i) are absent from
// every render, as SMACHA's SkipBlockExtension makes them. Errors propagate as TemplateError.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/generator/template_shape.h"
#include "backends/tmpl/environment.h"

namespace smachac::generator {

/// Block name → its snippet; the names point into the runner's per-template cache.
using BlockCode = std::vector<std::pair<std::string_view, std::string>>;
using Exports = std::vector<std::pair<std::string, tmpl::Value>>;

class TemplateRunner {
 public:
  TemplateRunner(tmpl::Environment& env, const TemplatePath& path,
                 std::vector<std::string> skip_blocks)
      : env_(env), shapes_(path), skip_{std::move(skip_blocks)} {}

  /// The template a script's `template: NAME` names, or nullopt.
  std::optional<std::string> resolve(std::string_view script_name);

  /// block → stripped snippet ("" or ending in one newline), for every block but `meta`.
  /// Blocks the template's shape shows to be empty are not rendered.
  BlockCode renderBlocks(const std::string& name, const tmpl::Value& vars);

  /// The template's exported variables after running it with `vars`. Only its top-level code
  /// runs: blocks export nothing, and their effects on shared values (defined_headers) have
  /// already happened in renderBlocks, where SMACHA's module pass would repeat them. Nothing
  /// runs when the template's shape shows it has nothing to export.
  Exports exports(const std::string& name, const tmpl::Value& vars);

  /// The same with the blocks run too, as SMACHA's module pass does: how the base template
  /// pre-seeds defined_headers with the imports its blocks write.
  Exports exportsRunningBlocks(const std::string& name, const tmpl::Value& vars);

  /// The whole template rendered with `vars`, stripped.
  std::string renderBase(const std::string& name, const tmpl::Value& vars);

  /// A block renderBlocks gives, and whether the template's shape shows it renders empty.
  struct Block {
    std::string name;
    bool renders_empty = false;
  };

  /// The blocks renderBlocks gives (sorted), worked out once per template.
  const std::vector<Block>& blocks(const std::string& name);

 private:
  Exports withoutLocalVars(Exports all);

  /// Options that remove every block of the template (and of what it references).
  const tmpl::RenderOptions& withoutBlocks(const std::string& name);

  tmpl::Environment& env_;
  TemplateShapes shapes_;
  tmpl::RenderOptions skip_;
  std::map<std::string, std::optional<std::string>, std::less<>> resolved_;
  std::map<std::string, std::vector<Block>, std::less<>> blocks_;
  std::map<std::string, tmpl::RenderOptions, std::less<>> without_blocks_;
};

}  // namespace smachac::generator
