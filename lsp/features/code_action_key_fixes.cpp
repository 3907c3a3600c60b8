// Quick fixes for userdata keys a state reads without declaring them:
//   * expr-key-not-input: add the key (the name the expression uses) to the `input_keys` of
//     the state whose callback holds the expression: the callback value written last before
//     the name (several states when they inherit the expression from one param)
//   * undefined-userdata-key, maybe-undefined-userdata-key with the note that the parent has
//     the key: add it to the `input_keys` of the container the note is at
#include <fmt/core.h>

#include <tuple>

#include "lsp/features/code_action_fixes.h"

namespace smachac::lsp {
namespace {

bool sameFile(const SourceLoc& a, const SourceLoc& b) { return a.file == b.file; }

auto linePosition(const SourceLoc& loc) { return std::tie(loc.line, loc.column); }

void addInputKey(FixContext& fix, const ir::State& state, const std::string& key) {
  const ir::Value* mapping = listOwner(fix, state, "input_keys");
  if (!mapping) return;
  YamlEdit edit = fix.edit();
  if (!edit.addToList(*mapping, "input_keys", key)) return;
  fix.offer(fmt::format("Add `{}` to the input_keys of `{}`", key, state.name.text), edit.result());
}

/// The start of the callback value of `state` written last at or before `at` (line 0: none).
SourceLoc callbackBefore(const ir::State& state, const SourceLoc& at) {
  SourceLoc best;
  for (const ir::Argument& callback : state.callbacks) {
    const SourceLoc& loc = callback.value.loc;
    if (!sameFile(loc, at) || linePosition(loc) > linePosition(at)) continue;
    if (linePosition(loc) > linePosition(best)) best = loc;
  }
  return best;
}

void fixExprKeyNotInput(FixContext& fix) {
  const SourceLoc& at = fix.diagnostic().loc;
  std::string key = fix.writtenText();
  if (key.empty()) return;
  SourceLoc closest;
  for (ir::StateId id : fix.module().preorder()) {
    SourceLoc loc = callbackBefore(fix.module().state(id), at);
    if (linePosition(loc) > linePosition(closest)) closest = loc;
  }
  if (!closest.hasLine()) return;
  for (ir::StateId id : fix.module().preorder()) {
    const ir::State& state = fix.module().state(id);
    if (callbackBefore(state, at) == closest) addInputKey(fix, state, key);
  }
}

/// The userdata key a read names at `at`: an input or output key of a state, or the parent's
/// key of a remapping.
const ir::Name* keyNamedAt(const FixContext& fix, const SourceLoc& at) {
  for (ir::StateId id : fix.module().preorder()) {
    const ir::State& state = fix.module().state(id);
    for (const std::vector<ir::Name>* names : {&state.input_keys, &state.output_keys}) {
      for (const ir::Name& name : *names) {
        if (name.loc == at) return &name;
      }
    }
    for (const ir::Remap& remap : state.remapping) {
      if (remap.parent_key.loc == at) return &remap.parent_key;
    }
  }
  return nullptr;
}

void fixUndefinedKey(FixContext& fix) {
  const ir::Name* key = keyNamedAt(fix, fix.diagnostic().loc);
  if (!key) return;
  for (const DiagNote& note : fix.diagnostic().notes) {
    const ir::State* container = fix.findState([&](const ir::State& s) {
      return isContainer(s.kind) && s.name.loc == note.loc && note.loc.hasFile();
    });
    if (container) addInputKey(fix, *container, key->text);
  }
}

}  // namespace

void addInputKeyFixes(FixContext& fix) {
  switch (fix.diagnostic().kind) {
    case DiagKind::ExprKeyNotInput:
      return fixExprKeyNotInput(fix);
    case DiagKind::UndefinedUserdataKey:
    case DiagKind::MaybeUndefinedUserdataKey:
      return fixUndefinedKey(fix);
    default:
      return;
  }
}

}  // namespace smachac::lsp
