// indexParams (index_builder.h): params from the document's YAML tree, where lookups are
// still written (the module holds their resolved values). Each `params` entry of the root or
// a state defines a param; a `[params, x]` or `[[x]]` lookup — a list value of a state key, a
// list value of a mapping under a state key, or a part of a string construct, where the
// frontend resolves them (frontend/lookups.h) — reads the nearest definition: the state's own
// `params`, then, for a state included from a sub-script, the sub-script state's, then its
// ancestors'. States are matched with the module's by the location of their names; a state
// the module does not have is skipped with everything inside it.
#include <unordered_map>

#include "frontend/shorthand.h"
#include "lsp/index_builder.h"

namespace smachac::lsp {
namespace {

using ir::StateId;

/// The value of script key `longhand` (or its shorthand) in a state's mapping.
const ir::Value* scriptKey(const ir::Value& vars, std::string_view longhand) {
  if (!vars.isMap()) return nullptr;
  const ir::Value* shorthand = nullptr;
  for (const ir::MapEntry& entry : vars.asMap()) {
    if (entry.key == longhand) return &entry.value;
    if (frontend::longhandOf(entry.key) == longhand) shorthand = &entry.value;
  }
  return shorthand;
}

/// The `x` of `[params, x]` or `[[x]]`, or null.
const ir::Value* lookupName(const ir::Value& value) {
  if (!value.isList()) return nullptr;
  const ir::List& items = value.asList();
  if (items.size() == 1 && items[0].isList() && items[0].asList().size() == 1 &&
      items[0].asList()[0].isString()) {
    return &items[0].asList()[0];
  }
  bool params = items.size() == 2 && items[0].isString() && items[0].asString() == "params";
  return params && items[1].isString() ? &items[1] : nullptr;
}

const ir::MapEntry* entryOf(const ir::Value* map, std::string_view key) {
  if (!map || !map->isMap()) return nullptr;
  for (const ir::MapEntry& entry : map->asMap()) {
    if (entry.key == key) return &entry;
  }
  return nullptr;
}

uint64_t locKey(const SourceLoc& loc) { return uint64_t{loc.line} << 32 | loc.column; }

class ParamWalk {
 public:
  ParamWalk(const Analysis& analysis, IndexBuilder& builder)
      : module_(*analysis.module), builder_(builder) {
    for (StateId id : module_.preorder()) {
      const SourceLoc& loc = module_.state(id).name.loc;
      if (loc.file == analysis.file) by_name_.emplace(locKey(loc), id);
    }
  }

  void run(const ir::Value& root) {
    if (root.isList()) return states(root);
    frames_.push_back({&root, module_.root()});
    definitions(root, module_.root());
    if (const ir::Value* list = scriptKey(root, "states")) states(*list);
  }

 private:
  struct Frame {
    const ir::Value* vars;
    StateId state;
  };

  void states(const ir::Value& list) {
    if (!list.isList()) return;
    for (const ir::Value& entry : list.asList()) {
      if (entry.isList()) {
        states(entry);
      } else if (entry.isMap() && entry.asMap().size() == 1) {
        state(entry.asMap().front());
      }
    }
  }

  void state(const ir::MapEntry& entry) {
    auto it = by_name_.find(locKey(entry.key_loc));
    if (it == by_name_.end() || !entry.value.isMap()) return;
    frames_.push_back({&entry.value, it->second});
    definitions(entry.value, it->second);
    lookups(entry.value, it->second);
    if (const ir::Value* list = scriptKey(entry.value, "states")) states(*list);
    frames_.pop_back();
  }

  void definitions(const ir::Value& vars, StateId id) {
    const ir::Value* params = scriptKey(vars, "params");
    if (!params || !params->isMap()) return;
    for (const ir::MapEntry& entry : params->asMap()) {
      builder_.add(entry.key_loc, builder_.param(entry.key_loc, entry.key), Role::Definition,
                   Site::Params, id, id);
    }
  }

  void lookups(const ir::Value& vars, StateId id) {
    for (const ir::MapEntry& entry : vars.asMap()) {
      if (frontend::longhandOf(entry.key).value_or(entry.key) == "states") continue;
      if (entry.value.isList()) lookupsIn(entry.value, id);
      if (!entry.value.isMap()) continue;
      for (const ir::MapEntry& inner : entry.value.asMap()) lookupsIn(inner.value, id);
    }
  }

  /// A lookup, or the lookups among the parts of a string construct.
  void lookupsIn(const ir::Value& value, StateId id) {
    if (const ir::Value* name = lookupName(value)) return lookup(*name, id);
    if (!value.isList()) return;
    for (const ir::Value& part : value.asList()) {
      if (const ir::Value* name = lookupName(part)) lookup(*name, id);
    }
  }

  void lookup(const ir::Value& name, StateId id) {
    auto [param, scope] = resolve(name.asString(), id);
    builder_.add(name.loc, param, Role::Reference, Site::Lookup, id, scope);
  }

  /// The param `name` a lookup of state `id` reads, and the state that defines it.
  std::pair<uint32_t, StateId> resolve(const std::string& name, StateId id) {
    for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame) {
      if (const ir::MapEntry* entry = entryOf(scriptKey(*frame->vars, "params"), name)) {
        return {builder_.param(entry->key_loc, name), frame->state};
      }
      if (const ir::MapEntry* entry = includedParam(frame->state, name)) {
        uint32_t param = builder_.param(entry->key_loc, name);
        builder_.add(entry->key_loc, param, Role::Definition, Site::Params, frame->state,
                     frame->state);
        return {param, frame->state};
      }
    }
    return {builder_.undefinedParam(id, name), id};
  }

  /// The `params` entry of the sub-script states `id` was included from, outermost first.
  const ir::MapEntry* includedParam(StateId id, const std::string& name) const {
    const std::vector<ir::Inclusion>& inclusions = module_.state(id).included_from;
    for (auto inclusion = inclusions.rbegin(); inclusion != inclusions.rend(); ++inclusion) {
      const ir::Value* params = inclusion->script_params ? &*inclusion->script_params : nullptr;
      if (const ir::MapEntry* entry = entryOf(params, name)) return entry;
    }
    return nullptr;
  }

  const ir::Module& module_;
  IndexBuilder& builder_;
  std::unordered_map<uint64_t, StateId> by_name_;
  std::vector<Frame> frames_;
};

}  // namespace

void indexParams(const Analysis& analysis, IndexBuilder& builder) {
  if (!analysis.yaml || !analysis.module) return;
  ParamWalk(analysis, builder).run(*analysis.yaml);
}

}  // namespace smachac::lsp
