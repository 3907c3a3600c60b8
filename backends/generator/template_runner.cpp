// Block rendering, module exports and the base render.
#include "backends/generator/template_runner.h"

#include <algorithm>
#include <unordered_set>

#include "backends/generator/code_buffers.h"

namespace smachac::generator {

std::optional<std::string> TemplateRunner::resolve(std::string_view script_name) {
  auto it = resolved_.find(script_name);
  if (it == resolved_.end()) {
    it = resolved_.emplace(std::string(script_name), env_.resolveScriptTemplate(script_name)).first;
  }
  return it->second;
}

const std::vector<TemplateRunner::Block>& TemplateRunner::blocks(const std::string& name) {
  auto it = blocks_.find(name);
  if (it != blocks_.end()) return it->second;
  const std::optional<TemplateShape>& shape = shapes_.shape(name);
  std::vector<Block> blocks;
  for (std::string& block : env_.listBlocks(name)) {
    bool skipped = std::find(skip_.skip_blocks.begin(), skip_.skip_blocks.end(), block) !=
                   skip_.skip_blocks.end();
    if (block == "meta" || skipped) continue;
    bool empty = shape && shape->rendersEmpty(block);
    blocks.push_back({std::move(block), empty});
  }
  return blocks_.emplace(name, std::move(blocks)).first->second;
}

BlockCode TemplateRunner::renderBlocks(const std::string& name, const tmpl::Value& vars) {
  const std::vector<Block>& template_blocks = blocks(name);
  BlockCode code;
  code.reserve(template_blocks.size());
  // Every other block is removed from a block render anyway, the skipped ones included.
  for (const Block& block : template_blocks) {
    code.emplace_back(
        block.name, block.renders_empty ? std::string() : env_.renderBlock(name, block.name, vars));
  }
  return code;
}

const tmpl::RenderOptions& TemplateRunner::withoutBlocks(const std::string& name) {
  auto it = without_blocks_.find(name);
  if (it == without_blocks_.end()) {
    it = without_blocks_.emplace(name, tmpl::RenderOptions{env_.listBlocks(name)}).first;
  }
  return it->second;
}

Exports TemplateRunner::exports(const std::string& name, const tmpl::Value& vars) {
  const std::optional<TemplateShape>& shape = shapes_.shape(name);
  if (shape && !shape->may_export) return {};
  return withoutLocalVars(env_.moduleVariables(name, vars, withoutBlocks(name)));
}

Exports TemplateRunner::exportsRunningBlocks(const std::string& name, const tmpl::Value& vars) {
  return withoutLocalVars(env_.moduleVariables(name, vars, skip_));
}

/// Drops the names an exported `local_vars` list names (SMACHA's local_var_lists).
Exports TemplateRunner::withoutLocalVars(Exports all) {
  std::unordered_set<std::string> local;
  for (const auto& [key, value] : all) {
    if (key != "local_vars" || !value.isListOrTuple()) continue;
    for (const tmpl::Value& item : value.list().items()) {
      if (item.isString()) local.insert(item.s());
    }
  }
  if (local.empty()) return all;
  Exports kept;
  for (auto& entry : all) {
    if (!local.count(entry.first)) kept.push_back(std::move(entry));
  }
  return kept;
}

std::string TemplateRunner::renderBase(const std::string& name, const tmpl::Value& vars) {
  tmpl::RenderOptions options = skip_;
  options.skip_blocks.push_back("meta");
  std::string code = env_.render(name, vars, options);
  stripInPlace(code);
  return code;
}

}  // namespace smachac::generator
