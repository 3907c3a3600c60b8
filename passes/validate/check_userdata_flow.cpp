// check-userdata-flow: every userdata key a state reads is defined before it runs, in the
// scope of its container (passes/analysis/userdata_scope.h says what defines, reads and
// writes a key; must_defined.h how "on every path" is computed). Reads are a child's
// `input_keys` through its remapping (except the input keys a child container has its own
// default for: SMACH only warns when it cannot copy them in) and, when a container finishes,
// its own `output_keys` (only checked to be defined somewhere in it: outputs that only some
// outcomes produce are common, and SMACH only warns when it cannot copy them out).
//   * undefined-userdata-key        nothing in the scope defines the key: no `userdata` of the
//                                   container or a leaf child, no input key of the container,
//                                   and no child writes it (did you mean: the scope's keys; a
//                                   note when the parent's scope has the key)
//   * maybe-undefined-userdata-key  some path reaches the read before any write: in a
//                                   StateMachine or the root, by the must-defined dataflow over
//                                   reachable states; in a Concurrence, whenever only the
//                                   children (which run in parallel) write the key and a
//                                   sibling of the reader does (when only the reader writes
//                                   it, the key is undefined when it starts: the error above).
//                                   Both note, when the parent's scope has the key, that the
//                                   container's `input_keys` would copy it in.
#include <fmt/core.h>

#include <string>
#include <unordered_map>

#include "ir/support/suggest.h"
#include "passes/analysis/children.h"
#include "passes/analysis/container_graph.h"
#include "passes/analysis/must_defined.h"
#include "passes/analysis/outcomes.h"
#include "passes/validate/checks.h"

namespace smachac::passes {
namespace {

/// The keys defined in each container's scope (initially or by a child), for hints.
using DefinedKeys = std::unordered_map<uint32_t, NameSet>;

constexpr uint32_t kExit = UINT32_MAX;  ///< "child" index of the container's output keys

class FlowChecker {
 public:
  FlowChecker(const ir::Module& module, ir::StateId id, PassContext& context)
      : module_(module),
        container_(module.state(id)),
        scope_(userdataScope(context, module, id)),
        diags_(context.diags) {}

  /// Records this scope's keys in `defined`; takes the parent's from it.
  void linkScopes(ir::StateId id, DefinedKeys& defined) {
    NameSet& keys = defined[id.index];
    for (uint32_t key = 0; key < scope_.keyCount(); ++key) {
      if (this->defined(key)) keys.insert(scope_.keyName(key));
    }
    if (container_.parent.valid()) parent_keys_ = &defined[container_.parent.index];
  }

  void run(const ChildIndex& index) {
    for (uint32_t child = 0; child < scope_.childCount(); ++child) {
      for (const KeyUse& read : scope_.reads(child)) checkDefined(child, read);
    }
    for (const KeyUse& read : scope_.exitReads()) checkDefined(kExit, read);
    if (isSequential(container_.kind)) {
      ContainerGraph graph = buildContainerGraph(module_, scope_.container(), index);
      for (const UndefinedRead& found : findMaybeUndefinedReads(graph, scope_)) {
        if (!found.use->optional) reportMaybe(found.child, *found.use);
      }
    } else {
      checkParallelReads();
    }
  }

 private:
  bool defined(uint32_t key) const { return scope_.initiallyDefined(key) || scope_.written(key); }

  void checkDefined(uint32_t child, const KeyUse& read) {
    if (!read.optional && !defined(read.key)) reportUndefined(child, read);
  }

  void reportUndefined(uint32_t child, const KeyUse& read) {
    if (names_.empty()) names_ = scope_.keyNames();
    std::optional<std::string> match = closestMatch(read.scope_name->text, names_);
    diags_.emit<DiagKind::UndefinedUserdataKey>(read.scope_name->loc, read.scope_name->text,
                                                reader(child, read), container_.name.text,
                                                didYouMean(match));
    diags_.fixIt(match);
    if (child != kExit) noteParentHasKey(read);
  }

  /// The actionable note when the parent's scope has the key the container does not copy in.
  void noteParentHasKey(const KeyUse& read) {
    if (!parent_keys_ || !parent_keys_->contains(read.scope_name->text)) return;
    const std::string& parent = module_.state(container_.parent).name.text;
    diags_.note<DiagNoteKind::ParentHasKey>(container_.name.loc, parent, read.scope_name->text,
                                            container_.name.text);
  }

  /// In a Concurrence, a key that only children write is undefined when they start: maybe
  /// undefined for a reader that a sibling races with, undefined for one only it writes.
  void checkParallelReads() {
    for (uint32_t child = 0; child < scope_.childCount(); ++child) {
      for (const KeyUse& read : scope_.reads(child)) {
        if (read.optional || scope_.initiallyDefined(read.key) || !scope_.written(read.key)) {
          continue;
        }
        if (writtenByOther(child, read.key)) {
          reportMaybe(child, read);
        } else {
          reportUndefined(child, read);
        }
      }
    }
  }

  bool writtenByOther(uint32_t reader, uint32_t key) const {
    for (uint32_t child = 0; child < scope_.childCount(); ++child) {
      for (const KeyUse& write : scope_.writes(child)) {
        if (child != reader && write.key == key) return true;
      }
    }
    return false;
  }

  void reportMaybe(uint32_t child, const KeyUse& read) {
    diags_.emit<DiagKind::MaybeUndefinedUserdataKey>(read.scope_name->loc, read.scope_name->text,
                                                     reader(child, read), container_.name.text);
    if (parent_keys_ && parent_keys_->contains(read.scope_name->text)) {
      noteParentHasKey(read);
    } else if (auto writer = scope_.firstWriter(read.key)) {
      diags_.note<DiagNoteKind::StateWritesKeyHere>(writer->second->scope_name->loc,
                                                    childName(module_, container_, writer->first));
    }
  }

  /// "read by `S`", "read by `S` as `k`" or "output by `C`".
  std::string reader(uint32_t child, const KeyUse& read) const {
    if (child == kExit) {
      return fmt::format("output by `{}`", container_.name.text);
    }
    if (read.name->text == read.scope_name->text) {
      return fmt::format("read by `{}`", childName(module_, container_, child));
    }
    return fmt::format("read by `{}` as `{}`", childName(module_, container_, child),
                       read.name->text);
  }

  const ir::Module& module_;
  const ir::State& container_;
  const UserdataScope& scope_;
  DiagnosticEmitter& diags_;
  std::vector<std::string> names_;
  const NameSet* parent_keys_ = nullptr;
};

}  // namespace

void checkUserdataFlow(const ir::Module& module, PassContext& context) {
  ChildIndex index(module);
  DefinedKeys defined;
  for (ir::StateId id : module.preorder()) {
    if (!ir::isContainer(module.state(id).kind)) continue;
    FlowChecker checker(module, id, context);
    checker.linkScopes(id, defined);
    checker.run(index);
  }
}

}  // namespace smachac::passes
