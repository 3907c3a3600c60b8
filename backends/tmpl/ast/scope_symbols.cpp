// The symbol table's updates that Jinja2's Symbols makes with more than a lookup: a store,
// the merge of an if's branches, and the names stored by a frame and its outer ones.
#include "backends/tmpl/ast/scope_symbols.h"

#include <algorithm>

namespace smachac::tmpl::scopes {

void Symbols::store(Name n) {
  addStore(n);
  if (owns(n)) return;
  if (parent) {
    if (const Symbols* outer = parent->findRef(n)) {
      defineRef(n, {SlotInitKind::Alias, outer});
      return;
    }
  }
  defineRef(n, {SlotInitKind::Undefined});
}

void Symbols::branchUpdate(std::initializer_list<const Symbols*> branches) {
  const size_t old_refs = refs.size();
  const size_t old_loads = loads.size();
  const size_t old_stores = stores.size();
  std::vector<std::pair<Name, size_t>> counts;
  for (const Symbols* branch : branches) {
    if (!branch) continue;
    const Symbols& b = *branch;
    for (size_t i = old_stores; i < b.stores.size(); ++i) {
      Name t = b.stores[i];
      auto it = std::find_if(counts.begin(), counts.end(), [&](auto& c) { return c.first == t; });
      if (it == counts.end()) {
        counts.emplace_back(t, 1);
      } else {
        ++it->second;
      }
    }
  }
  for (const Symbols* branch : branches) {
    if (!branch) continue;
    const Symbols& b = *branch;
    for (size_t i = old_refs; i < b.refs.size(); ++i) {
      if (!owns(b.refs[i])) refs.push_back(b.refs[i]);
    }
    for (size_t i = old_loads; i < b.loads.size(); ++i) {
      setLoad(b.loads[i].first, b.loads[i].second);
    }
    for (size_t i = old_stores; i < b.stores.size(); ++i) addStore(b.stores[i]);
  }
  // Every branch sets every entry this level had, so the last branch's values hold (this
  // level's own, when that branch ran nothing).
  if (const Symbols* last = *(branches.end() - 1)) {
    for (size_t i = 0; i < old_loads; ++i) loads[i].second = last->loads[i].second;
  }
  for (const auto& [n, count] : counts) {
    if (count == branches.size()) continue;
    const Symbols* outer = parent ? parent->findRef(n) : nullptr;
    setLoad(n, outer ? Load{SlotInitKind::Alias, outer} : Load{SlotInitKind::Resolve});
  }
}

std::vector<Name> Symbols::dumpStores() const {
  std::vector<Name> out;
  for (const Symbols* s = this; s; s = s->parent) {
    std::vector<Name> sorted = s->stores;
    std::sort(sorted.begin(), sorted.end(), [](Name a, Name b) { return *a < *b; });
    for (Name n : sorted) {
      if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
    }
  }
  return out;
}

}  // namespace smachac::tmpl::scopes
