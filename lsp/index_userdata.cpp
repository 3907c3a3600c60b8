// indexUserdata (index_builder.h): the userdata keys of each container's scope, as
// passes/analysis/userdata_scope.h models it. In the scope of container C:
//   * C's `userdata` and its leaves' are definitions of C's keys;
//   * C's input keys and output keys are references to C's keys;
//   * a child's input keys read, and its output keys write, C's key through its remapping:
//     the remapping's value (or the key itself, unremapped) is C's key, a definition when a
//     leaf writes it; a remapped name is the child's own, fed by C's key when read, feeding
//     it when a container writes it;
//   * a `remapping` key is the state's own name; its value a name of the parent's scope.
// An unremapped key of a container's interface is written once and recorded in both scopes,
// so it joins the two (IndexBuilder records a location once).
#include "lsp/index_builder.h"
#include "passes/analysis/userdata_scope.h"

namespace smachac::lsp {
namespace {

using ir::StateId;
using passes::KeyUse;
using passes::UserdataScope;

void indexInterface(const ir::Module& module, const UserdataScope& scope, IndexBuilder& b) {
  StateId c = scope.container();
  for (const passes::LiteralDef& literal : scope.literals()) {
    const ir::Name& key = literal.arg->key;
    StateId holder =
        literal.child == UserdataScope::kContainer ? c : module.state(c).children[literal.child];
    b.add(key, b.key(c, key.text), Role::Definition, Site::Userdata, holder, c);
  }
  for (const KeyUse& use : scope.inputs()) {
    b.add(*use.name, b.key(c, use.name->text), Role::Reference, Site::InputKeys, c, c);
  }
  for (const KeyUse& use : scope.exitReads()) {
    b.add(*use.name, b.key(c, use.name->text), Role::Reference, Site::OutputKeys, c, c);
  }
}

/// One read or write of child `child` in `scope`.
void indexUse(const UserdataScope& scope, StateId child, bool leaf, const KeyUse& use, bool write,
              IndexBuilder& b) {
  StateId c = scope.container();
  Site site = write ? Site::OutputKeys : Site::InputKeys;
  Role role = write && leaf ? Role::Definition : Role::Reference;
  uint32_t outer = b.key(c, use.scope_name->text);
  if (use.scope_name == use.name) return b.add(*use.name, outer, role, site, child, c);
  b.add(*use.scope_name, outer, role, Site::RemapValue, child, c);
  uint32_t own = b.key(child, use.name->text);
  b.add(*use.name, own, role, site, child, child);
  if (write && !leaf) {
    b.feed(outer, own);
  } else {
    b.feed(own, outer);
  }
}

void indexChildren(const ir::Module& module, const UserdataScope& scope, IndexBuilder& b) {
  const ir::State& container = module.state(scope.container());
  for (uint32_t i = 0; i < scope.childCount(); ++i) {
    StateId child = container.children[i];
    bool leaf = !ir::isContainer(module.state(child).kind);
    for (const KeyUse& use : scope.reads(i)) indexUse(scope, child, leaf, use, false, b);
    for (const KeyUse& use : scope.writes(i)) indexUse(scope, child, leaf, use, true, b);
  }
}

/// Every `remapping` entry (the ones input and output keys use are recorded already).
void indexRemapping(const ir::Module& module, StateId id, IndexBuilder& b) {
  const ir::State& s = module.state(id);
  for (const ir::Remap& remap : s.remapping) {
    b.add(remap.key, b.key(id, remap.key.text), Role::Reference, Site::RemapKey, id, id);
    if (!s.parent.valid()) continue;
    b.add(remap.parent_key, b.key(s.parent, remap.parent_key.text), Role::Reference,
          Site::RemapValue, id, s.parent);
  }
}

}  // namespace

void indexUserdata(const ir::Module& module, IndexBuilder& builder) {
  for (StateId id : module.preorder()) {
    if (ir::isContainer(module.state(id).kind)) {
      UserdataScope scope(module, id);
      indexInterface(module, scope, builder);
      indexChildren(module, scope, builder);
    }
  }
  for (StateId id : module.preorder()) indexRemapping(module, id, builder);
}

}  // namespace smachac::lsp
