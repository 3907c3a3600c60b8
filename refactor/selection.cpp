// Resolving state names given on the command line.
#include "refactor/selection.h"

#include <fmt/core.h>

#include "ir/support/suggest.h"

namespace smachac::refactor {
namespace {

std::string quotedNames(std::span<const std::string> names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "`" : ", `") + name + "`";
  return out;
}

void noteRootStates(const ScriptView& script, DiagnosticEmitter& diags) {
  diags.note<DiagNoteKind::RootStatesAre>({}, quotedNames(script.names()));
}

/// A state of that name nested in a container, if any.
std::optional<ir::StateId> findNested(const ir::Module& module, std::string_view name) {
  for (ir::StateId id : module.preorder()) {
    const ir::State& state = module.state(id);
    if (state.name.text == name && state.parent.valid() && state.parent != module.root()) {
      return id;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<size_t> findRootState(const ScriptView& script, std::string_view name,
                                    std::string_view tool, DiagnosticEmitter& diags) {
  if (std::optional<size_t> index = script.find(name)) return index;
  const ir::Module& module = script.module();
  if (std::optional<ir::StateId> nested = findNested(module, name)) {
    const ir::State& state = module.state(*nested);
    diags.emit<DiagKind::StateNotAtRoot>(state.name.loc, name, module.state(state.parent).name.text,
                                         tool);
    return std::nullopt;
  }
  std::vector<std::string> names = script.names();
  diags.emit<DiagKind::UnknownRootState>(script.statesEntry().key_loc, name,
                                         didYouMean(name, names));
  noteRootStates(script, diags);
  return std::nullopt;
}

std::optional<Selection> selectRun(const ScriptView& script, std::span<const std::string> names,
                                   DiagnosticEmitter& diags) {
  std::vector<size_t> indices;
  for (const std::string& name : names) {
    std::optional<size_t> index = findRootState(script, name, "contain", diags);
    if (index) indices.push_back(*index);
  }
  if (indices.size() != names.size()) return std::nullopt;
  const std::vector<RootState>& states = script.states();
  Selection run{indices.front(), indices.size()};
  for (size_t k = 1; k < indices.size(); ++k) {
    size_t expected = run.first + k;
    bool same_list = expected < states.size() && states[expected].list == states[run.first].list;
    if (indices[k] == expected && same_list) continue;
    std::string found;
    if (expected >= states.size()) {
      found = fmt::format("`{}` is the last root state, so `{}` cannot follow it", names[k - 1],
                          names[k]);
    } else if (indices[k] != expected) {
      found = fmt::format("`{}` is followed by `{}`, not `{}`", names[k - 1],
                          states[expected].name(), names[k]);
    } else {
      found = fmt::format("`{}` is in another list of states", names[k]);
    }
    diags.emit<DiagKind::SelectionNotConsecutive>(states[indices[k]].entry->key_loc, found);
    noteRootStates(script, diags);
    return std::nullopt;
  }
  return run;
}

}  // namespace smachac::refactor
