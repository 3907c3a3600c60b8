// The streamed attempt (streamed_lowering.h): a StatesSink of the fast reader that lowers
// each finished leaf of the root's `states` at once and frees it.
#include "frontend/streamed_lowering.h"

#include "frontend/lowering.h"
#include "frontend/simple_yaml_reader.h"
#include "ir/support/utf8.h"

namespace smachac::frontend {
namespace {

using ir::Value;

/// Lowers the main script's states while the fast reader is still reading the rest, so that
/// a big script's whole YAML tree never exists: each item of the root's `states` list is
/// lowered as soon as it is complete and then freed. The root state is built from the root's
/// keys before `states`. The result is the classic one (parse everything, then lower) or
/// nothing: `lowerScript` lowers the classic way, with this attempt's diagnostics taken back,
/// when the fast reader gives up or a root key follows `states`. Only leaves are lowered
/// early (a container or an inclusion stops it; the rest is lowered after the read), so the
/// attempt never reads another file.
class StreamedLowering : public StatesSink {
 public:
  StreamedLowering(const FrontendOptions& options, SourceManager& sources, DiagnosticEmitter& diags,
                   uint32_t file)
      : options_(options), sources_(sources), diags_(diags), file_(file) {}

  bool take(Value& item, const StatesListSite& site) override {
    if (stopped_) return false;
    if (!lowering_ && !start(site)) return false;
    if (!isLeafEntry(item)) {
      stopped_ = true;
      return false;
    }
    lowering_->lowerRootEntry(item);
    return true;
  }

  /// Whether the attempt lowered anything (else the caller lowers the tree the classic way).
  bool started() const { return lowering_.has_value(); }
  /// The module, once the reader finished with the tree `root` (that lacks the states taken);
  /// nullopt in `done` when the classic way must lower the script instead.
  std::optional<ir::Module> finish(Value& root, bool& done) {
    done = !root.asMap().empty() && root.asMap().back().key == "states";
    if (!done) return std::nullopt;
    std::optional<ir::Module> module;
    if (root_complete_) module = lowering_->finishStreamed(root.asMap().back().value);
    if (options_.include_sites) *options_.include_sites = lowering_->includeSites();
    return module;
  }

 private:
  bool start(const StatesListSite& site) {
    Value partial = Value::map(site.root_entries, site.root_loc);
    partial.asMap().push_back({"states", site.states_key_loc, Value::list({}, site.list_loc)});
    lowering_.emplace(options_, sources_, diags_);
    root_complete_ = lowering_->startStreamed(file_, partial);
    stopped_ = !root_complete_;
    return root_complete_;
  }

  /// `{NAME: {...}}` without `states` or `script` (shorthands included).
  static bool isLeafEntry(const Value& item) {
    if (!item.isMap() || item.asMap().size() != 1) return false;
    const Value& body = item.asMap().front().value;
    if (!body.isMap()) return false;
    for (const ir::MapEntry& e : body.asMap()) {
      if (e.key == "states" || e.key == "s" || e.key == "script" || e.key == "S") return false;
    }
    return true;
  }

  const FrontendOptions& options_;
  SourceManager& sources_;
  DiagnosticEmitter& diags_;
  uint32_t file_;
  std::optional<Lowering> lowering_;
  bool root_complete_ = false;
  bool stopped_ = false;
};

}  // namespace

std::optional<ir::Module> lowerStreamed(uint32_t file, const FrontendOptions& options,
                                        SourceManager& sources, DiagnosticEmitter& diags,
                                        bool& done) {
  done = false;
  std::string_view text = sources.content(file);
  if (findInvalidUtf8(text)) return std::nullopt;
  size_t first_diagnostic = diags.diagnostics().size();
  StreamedLowering streamed(options, sources, diags, file);
  std::optional<Value> root = readSimpleYaml(file, text, &streamed);
  if (root && !streamed.started()) {
    done = true;
    return lowerTree(file, std::move(*root), options, sources, diags);
  }
  std::optional<ir::Module> module;
  if (root) module = streamed.finish(*root, done);
  if (!done) diags.replaceFrom(first_diagnostic, {});
  return module;
}

}  // namespace smachac::frontend
