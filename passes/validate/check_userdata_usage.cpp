// check-userdata-usage: userdata definitions that have no effect, per container scope
// (passes/analysis/userdata_scope.h).
//   * overwritten-userdata  a `userdata` entry that a later entry for the same key in the same
//                           scope replaces with a different value when the container is built,
//                           before any state can see it (the container's entries come first,
//                           then each child's in order)
//   * unused-userdata-key   (-Wno-unused-userdata-key silences it) a key set in a scope, by a
//                           `userdata` entry or a child's output key, that no child reads and
//                           the container does not output; reported at its first definition.
//                           Not checked in a scope with a leaf that declares no `input_keys`
//                           (its template may read any key); the keys written in the
//                           script's root scope are its results.
#include <string>
#include <vector>

#include "passes/analysis/children.h"
#include "passes/analysis/userdata_scope.h"
#include "passes/validate/checks.h"

namespace smachac::passes {
namespace {

class UsageChecker {
 public:
  UsageChecker(const ir::Module& module, ir::StateId id, PassContext& context)
      : module_(module),
        container_(module.state(id)),
        scope_(userdataScope(context, module, id)),
        diags_(context.diags) {}

  void run() {
    reportOverwritten();
    reportUnused();
  }

 private:
  void reportOverwritten() {
    std::vector<const LiteralDef*> last(scope_.keyCount(), nullptr);
    for (const LiteralDef& def : scope_.literals()) {
      const LiteralDef* previous = last[def.key];
      last[def.key] = &def;
      if (!previous || ir::sameValue(previous->arg->value, def.arg->value)) continue;
      diags_.emit<DiagKind::OverwrittenUserdata>(previous->arg->key.loc, def.arg->key.text,
                                                 definer(def.child), container_.name.text);
      diags_.note<DiagNoteKind::KeySetAgainHere>(def.arg->key.loc);
    }
  }

  void reportUnused() {
    if (hasUnknownReader()) return;
    std::vector<uint8_t> read(scope_.keyCount(), 0);
    for (uint32_t child = 0; child < scope_.childCount(); ++child) {
      for (const KeyUse& use : scope_.reads(child)) read[use.key] = 1;
    }
    for (const KeyUse& use : scope_.exitReads()) read[use.key] = 1;
    if (container_.kind == ir::StateKind::Base) markResults(read);
    for (const LiteralDef& def : scope_.literals()) reportOnce(def.key, def.arg->key, read);
    for (uint32_t child = 0; child < scope_.childCount(); ++child) {
      for (const KeyUse& use : scope_.writes(child)) reportOnce(use.key, *use.scope_name, read);
    }
  }

  /// A leaf that declares no `input_keys` reads those its template declares, unseen here:
  /// it may read any key of the scope.
  bool hasUnknownReader() const {
    for (ir::StateId id : container_.children) {
      const ir::State& child = module_.state(id);
      if (!ir::isContainer(child.kind) && child.input_keys.empty()) return true;
    }
    return false;
  }

  /// The keys the states of the script write are its results, which the program running it
  /// reads (the final userdata): neither they nor their initial values are unused.
  void markResults(std::vector<uint8_t>& read) const {
    for (uint32_t child = 0; child < scope_.childCount(); ++child) {
      for (const KeyUse& use : scope_.writes(child)) read[use.key] = 1;
    }
  }

  /// Reports `key` at `where` unless it is read or was reported; marks it reported.
  void reportOnce(uint32_t key, const ir::Name& where, std::vector<uint8_t>& read) {
    if (read[key]) return;
    read[key] = 1;
    diags_.emit<DiagKind::UnusedUserdataKey>(where.loc, where.text, container_.name.text);
  }

  const std::string& definer(uint32_t child) const {
    if (child == UserdataScope::kContainer) return container_.name.text;
    return childName(module_, container_, child);
  }

  const ir::Module& module_;
  const ir::State& container_;
  const UserdataScope& scope_;
  DiagnosticEmitter& diags_;
};

}  // namespace

void checkUserdataUsage(const ir::Module& module, PassContext& context) {
  for (ir::StateId id : module.preorder()) {
    if (ir::isContainer(module.state(id).kind)) UsageChecker(module, id, context).run();
  }
}

}  // namespace smachac::passes
