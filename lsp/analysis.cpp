// Running the checks on an editor's document.
#include "lsp/analysis.h"

#include <filesystem>
#include <memory>

#include "frontend/shorthand.h"
#include "frontend/yaml_loader.h"
#include "lsp/uri.h"

namespace smachac::lsp {
namespace {

bool isScriptKey(std::string_view key) {
  std::string_view longhand = frontend::longhandOf(key).value_or(key);
  for (std::string_view script_key : {"name", "template", "states", "script", "outcomes"}) {
    if (longhand == script_key) return true;
  }
  return false;
}

/// The canonical paths of the files an analysis read but the document itself.
std::set<std::string> otherFiles(const SourceManager& sources, const std::string& document) {
  std::set<std::string> paths;
  for (uint32_t id = 1; id <= sources.fileCount(); ++id) {
    if (sources.path(id) == document) continue;
    std::error_code ec;
    std::string canonical = std::filesystem::weakly_canonical(sources.path(id), ec).string();
    paths.insert(ec ? sources.path(id) : canonical);
  }
  return paths;
}

}  // namespace

bool looksLikeScript(const ir::Value& root) {
  if (root.isMap()) {
    for (const ir::MapEntry& entry : root.asMap()) {
      if (isScriptKey(entry.key)) return true;
    }
    return false;
  }
  if (!root.isList() || root.asList().size() != 1) return false;
  const ir::Value& state = root.asList().front();
  return state.isMap() && state.asMap().size() == 1 && state.asMap().front().value.isMap();
}

std::string Analysis::uriOf(uint32_t file_id) const {
  if (file_id == file) return uri;
  return uriFromPath(std::filesystem::absolute(sources.path(file_id)).lexically_normal().string());
}

std::unique_ptr<Analysis> analyze(const Document& document, const Settings& settings,
                                  const frontend::DocumentOverlay& overlay) {
  auto analysis = std::make_unique<Analysis>();
  analysis->uri = document.uri;
  analysis->version = document.version;
  checker::CheckOptions options = checkOptions(settings);
  options.overlay = &overlay;
  DiagnosticEmitter diags(warningOptions(settings));
  checker::CheckedScript checked =
      checker::checkScript(document.name, document.text, options, analysis->sources, diags);
  analysis->file = 1;  // the first file the check registered
  DiagnosticEmitter yaml_diags;
  analysis->yaml = frontend::parseYaml(analysis->file, analysis->sources, yaml_diags);
  analysis->is_script = !analysis->yaml || looksLikeScript(*analysis->yaml);
  if (!analysis->is_script) return analysis;
  analysis->module = std::move(checked.module);
  analysis->ok = checked.ok;
  analysis->include_sites = std::move(checked.include_sites);
  analysis->diagnostics = diags.diagnostics();
  analysis->dependencies = otherFiles(analysis->sources, document.name);
  return analysis;
}

}  // namespace smachac::lsp
