// contain and extract as code actions.
#include "lsp/features/code_action_refactors.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

#include "lsp/uri.h"
#include "refactor/contain.h"
#include "refactor/extract.h"
#include "refactor/yaml_spans.h"

namespace smachac::lsp {
namespace {

namespace fs = std::filesystem;

/// The request's range in bytes of the document.
struct ByteRange {
  size_t begin = 0;
  size_t end = 0;
};

class Refactorer {
 public:
  Refactorer(const ActionRequest& request, const refactor::ScriptView& view)
      : request_(request), view_(view) {
    LineIndex lines = request.analysis.lines();
    range_ = {lines.offsetOf(request.range.start), lines.offsetOf(request.range.end)};
  }

  void contain(std::vector<Json>& actions) const;
  void extract(std::vector<Json>& actions) const;

 private:
  std::vector<std::string> touchedStates() const;
  std::string containerName() const;
  std::optional<std::string> containText(const std::vector<std::string>& states,
                                         ir::StateKind kind) const;
  std::optional<size_t> stateNamed() const;
  std::optional<std::string> subScriptStem(const fs::path& dir, const std::string& state) const;
  bool taken(const fs::path& path) const;

  const ActionRequest& request_;
  const refactor::ScriptView& view_;
  ByteRange range_;
};

std::vector<std::string> Refactorer::touchedStates() const {
  std::vector<std::string> names;
  for (const refactor::RootState& state : view_.states()) {
    refactor::Span span = refactor::listItemSpan(view_.text(), *state.list, *state.item);
    if (span.begin < range_.end && range_.begin < span.end) names.push_back(state.name());
  }
  return names;
}

std::string Refactorer::containerName() const {
  const ir::Module& module = view_.module();
  std::set<std::string, std::less<>> taken;
  for (ir::StateId id : module.preorder()) taken.insert(module.state(id).name.text);
  for (const ir::Name& outcome : module.state(module.root()).outcomes) taken.insert(outcome.text);
  std::string name = "CONTAINER";
  for (int k = 2; taken.contains(name); ++k) name = fmt::format("CONTAINER_{}", k);
  return name;
}

std::optional<std::string> Refactorer::containText(const std::vector<std::string>& states,
                                                   ir::StateKind kind) const {
  refactor::ContainRequest contain{containerName(), kind, states, std::nullopt};
  DiagnosticEmitter diags;
  return refactor::contain(view_, contain, diags);
}

std::string describeStates(const std::vector<std::string>& states) {
  if (states.size() == 1) return fmt::format("`{}`", states.front());
  return fmt::format("`{}` to `{}`", states.front(), states.back());
}

void Refactorer::contain(std::vector<Json>& actions) const {
  if (range_.begin == range_.end) return;
  std::vector<std::string> states = touchedStates();
  if (states.empty()) return;
  for (ir::StateKind kind : {ir::StateKind::StateMachine, ir::StateKind::Concurrence}) {
    std::optional<std::string> text = containText(states, kind);
    if (!text) continue;
    std::string title =
        fmt::format("Contain {} in a new {}", describeStates(states),
                    kind == ir::StateKind::StateMachine ? "StateMachine" : "Concurrence");
    actions.push_back(codeActionJson(title, action_kind::kRewrite, documentEdit(request_, *text)));
  }
}

std::optional<size_t> Refactorer::stateNamed() const {
  for (size_t i = 0; i < view_.states().size(); ++i) {
    refactor::Span key = refactor::keySpan(view_.text(), *view_.states()[i].entry);
    if (key.begin <= range_.begin && range_.end <= key.end) return i;
  }
  return std::nullopt;
}

/// The state's name in lower case, when it can name a file.
std::optional<std::string> fileStem(const std::string& state) {
  std::string stem;
  for (unsigned char c : state) {
    if (!std::isalnum(c) && c != '_' && c != '-') return std::nullopt;
    stem += static_cast<char>(std::tolower(c));
  }
  if (stem.empty()) return std::nullopt;
  return stem;
}

bool Refactorer::taken(const fs::path& path) const {
  std::error_code ec;
  if (fs::exists(path, ec) || ec) return true;
  fs::path canonical = fs::weakly_canonical(path, ec);
  return request_.overlay.contains((ec ? path : canonical).string());
}

std::optional<std::string> Refactorer::subScriptStem(const fs::path& dir,
                                                     const std::string& state) const {
  std::optional<std::string> base = fileStem(state);
  if (!base) return std::nullopt;
  std::string stem = *base;
  for (int k = 2; taken(dir / stem) || taken(dir / (stem + ".yml")); ++k) {
    stem = fmt::format("{}_{}", *base, k);
  }
  return stem;
}

void Refactorer::extract(std::vector<Json>& actions) const {
  WorkspaceEdit edit(request_.support);
  std::optional<std::string> path = pathFromUri(request_.document.uri);
  std::optional<size_t> index = stateNamed();
  if (!edit.canCreateFiles() || !path || !index) return;
  const std::string& state = view_.states()[*index].name();
  fs::path dir = fs::path(*path).parent_path();
  std::optional<std::string> stem = subScriptStem(dir, state);
  if (!stem) return;
  DiagnosticEmitter diags;
  std::optional<refactor::ExtractResult> result = refactor::extract(view_, state, *stem, diags);
  if (!result) return;
  std::string sub_uri = uriFromPath((dir / (*stem + ".yml")).string());
  edit.createFile(sub_uri);
  edit.editDocument(sub_uri, std::nullopt, {TextEdit{{}, result->sub_script}});
  edit.editDocument(request_.analysis.uri, request_.analysis.version,
                    diffEdits(request_.analysis.text(), result->super_script));
  std::string title = fmt::format("Extract `{}` into sub-script `{}.yml`", state, *stem);
  actions.push_back(codeActionJson(title, action_kind::kExtract, edit));
}

/// Whether the request's range lies within the name of a root state (a cheap test on the
/// analysis, before the script is loaded again for extract).
bool withinRootStateName(const ActionRequest& request) {
  const Analysis& analysis = request.analysis;
  if (!analysis.module) return false;
  const ir::Module& module = *analysis.module;
  LineIndex lines = analysis.lines();
  for (ir::StateId id : module.state(module.root()).children) {
    const SourceLoc& loc = module.state(id).name.loc;
    if (loc.file != analysis.file) continue;
    Range name = lines.rangeOf(loc);
    if (name.start <= request.range.start && request.range.end <= name.end) return true;
  }
  return false;
}

}  // namespace

std::vector<Json> refactorActions(const ActionRequest& request, RefactorKinds kinds) {
  bool selection = request.range.start != request.range.end;
  kinds.contain = kinds.contain && selection;
  kinds.extract = kinds.extract && withinRootStateName(request);
  if (!kinds.contain && !kinds.extract) return {};
  SourceManager sources;
  DiagnosticEmitter diags;
  frontend::FrontendOptions options{request.settings.script_dirs, nullptr, false, &request.overlay,
                                    false};
  std::optional<refactor::ScriptView> view = refactor::ScriptView::loadText(
      request.document.name, std::string(request.analysis.text()), options, sources, diags);
  if (!view) return {};
  std::vector<Json> actions;
  Refactorer refactorer(request, *view);
  if (kinds.contain) refactorer.contain(actions);
  if (kinds.extract) refactorer.extract(actions);
  return actions;
}

}  // namespace smachac::lsp
