// check-userdata-types: the types of userdata keys where a container copies them in from or
// out to its parent (its `input_keys` and `output_keys`, through its remapping). A key's type
// in a scope comes from its effective literal (ir::Type::ofValue of the last `userdata` entry
// for it in the scope) or, for an input key without one, from the parent's key it is copied
// from. Templates do not declare key types yet, so leaves are not checked.
//   * userdata-type-mismatch  a container's literal for one of its input or output keys has a
//                             type incompatible with the parent's key. Compatible: equal types,
//                             int and float, lists or maps of compatible elements; null,
//                             expressions (`code`) and mixed types match anything.
#include <fmt/core.h>

#include <string>
#include <string_view>
#include <unordered_map>

#include "ir/type.h"
#include "passes/analysis/outcomes.h"
#include "passes/analysis/userdata_scope.h"
#include "passes/validate/checks.h"

namespace smachac::passes {
namespace {

/// Where a key's type in a scope comes from.
struct TypedKey {
  ir::Type type = ir::Type::any();
  SourceLoc loc;           ///< the literal
  std::string_view scope;  ///< the container the literal is in
  std::string_view name;   ///< the key's name there
  bool inherited = false;  ///< copied in from the parent
};
using TypeTable = std::unordered_map<std::string_view, TypedKey>;

bool compatible(const ir::Type& a, const ir::Type& b) {
  using Kind = ir::Type::Kind;
  auto loose = [](Kind k) { return k == Kind::Any || k == Kind::Null || k == Kind::Expression; };
  auto numeric = [](Kind k) { return k == Kind::Int || k == Kind::Float; };
  if (loose(a.kind()) || loose(b.kind())) return true;
  if (numeric(a.kind()) && numeric(b.kind())) return true;
  if (a.kind() != b.kind()) return false;
  if (a.kind() == Kind::ListOf || a.kind() == Kind::MapOf) {
    return compatible(a.element(), b.element());
  }
  return true;
}

TypeTable literalTypes(PassContext& context, const ir::Module& module, ir::StateId id) {
  const ir::State& container = module.state(id);
  TypeTable table;
  const UserdataScope& scope = userdataScope(context, module, id);
  for (const LiteralDef& def : scope.literals()) {
    table[def.arg->key.text] = {ir::Type::ofValue(def.arg->value), def.arg->value.loc,
                                container.name.text, def.arg->key.text, false};
  }
  return table;
}

class TypeChecker {
 public:
  TypeChecker(const ir::Module& module, PassContext& context)
      : module_(module), context_(context), diags_(context.diags) {}

  void run() {
    for (ir::StateId id : module_.preorder()) {
      if (!ir::isContainer(module_.state(id).kind)) continue;
      TypeTable& table = tables_[id.index] = literalTypes(context_, module_, id);
      ir::StateId parent = module_.state(id).parent;
      if (parent.valid()) checkInterface(module_.state(id), table, tables_[parent.index]);
    }
  }

 private:
  void checkInterface(const ir::State& container, TypeTable& table, const TypeTable& outer) {
    NameSet seen;
    for (const ir::Name& key : container.input_keys) {
      if (seen.insert(key.text).second) checkKey(container, key, true, table, outer);
    }
    for (const ir::Name& key : container.output_keys) {
      if (seen.insert(key.text).second) checkKey(container, key, false, table, outer);
    }
  }

  /// Compares the container's literal for `key` with the parent's key; an input key without
  /// a literal takes the parent's type instead.
  void checkKey(const ir::State& container, const ir::Name& key, bool input, TypeTable& table,
                const TypeTable& outer) {
    auto from = outer.find(remappedName(container, key).text);
    if (from == outer.end()) return;
    auto it = table.find(key.text);
    if (it == table.end()) {
      if (input) table.emplace(key.text, from->second).first->second.inherited = true;
    } else if (!it->second.inherited && !compatible(it->second.type, from->second.type)) {
      report(key.text, it->second, from->second);
    }
  }

  void report(std::string_view key, const TypedKey& inner, const TypedKey& outer) {
    std::string as = outer.name == key ? "" : fmt::format(" (as `{}`)", outer.name);
    diags_.emit<DiagKind::UserdataTypeMismatch>(inner.loc, key, inner.type.str(), outer.type.str(),
                                                outer.scope, as);
    diags_.note<DiagNoteKind::KeySetHere>(outer.loc, outer.name);
  }

  const ir::Module& module_;
  PassContext& context_;
  DiagnosticEmitter& diags_;
  std::unordered_map<uint32_t, TypeTable> tables_;
};

}  // namespace

void checkUserdataTypes(const ir::Module& module, PassContext& context) {
  TypeChecker(module, context).run();
}

}  // namespace smachac::passes
