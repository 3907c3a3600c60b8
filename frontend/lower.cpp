// The frontend's entry points (lower.h): a script file or text, lowered while it is read
// when it can be (streamed_lowering.h), else read whole and then lowered (lowering.h).
#include "frontend/lower.h"

#include "frontend/lowering.h"
#include "frontend/streamed_lowering.h"
#include "frontend/yaml_loader.h"

namespace smachac::frontend {
namespace {

/// A script whose text is registered as `file` (0: it could not be read).
std::optional<ir::Module> lowerFile(uint32_t file, const FrontendOptions& options,
                                    SourceManager& sources, DiagnosticEmitter& diags) {
  // A sub-script's root is a list: the streamed attempt leaves it to lowerTree.
  if (file != 0 && options.stream_states) {
    bool done = false;
    std::optional<ir::Module> module = lowerStreamed(file, options, sources, diags, done);
    if (done) return module;
  }
  std::optional<ir::Value> root;
  if (file != 0) root = parseYaml(file, sources, diags);
  if (!root) {
    if (options.include_sites) *options.include_sites = {};
    return std::nullopt;
  }
  return lowerTree(file, std::move(*root), options, sources, diags);
}

}  // namespace

std::optional<ir::Module> lowerScript(const std::string& path, const FrontendOptions& options,
                                      SourceManager& sources, DiagnosticEmitter& diags) {
  return lowerFile(readYamlFile(path, {}, sources, diags), options, sources, diags);
}

std::optional<ir::Module> lowerScriptText(const std::string& path, std::string text,
                                          const FrontendOptions& options, SourceManager& sources,
                                          DiagnosticEmitter& diags) {
  return lowerFile(sources.addFile(path, std::move(text)), options, sources, diags);
}

}  // namespace smachac::frontend
