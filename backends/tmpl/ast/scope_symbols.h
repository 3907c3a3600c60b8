// Jinja2's symbol table of one level of scope analysis (scope.cpp): the names a frame owns,
// how each is loaded when the frame starts, and the names stored in it. Names are interned,
// so they are compared by address.
#pragma once

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "backends/tmpl/ast/ast.h"

namespace smachac::tmpl::scopes {

using Name = const std::string*;

struct Load {
  SlotInitKind kind;
  const struct Symbols* alias_owner = nullptr;
};

// Jinja's Symbols: refs (names owned by this level), their load instructions and stores.
struct Symbols {
  const Symbols* parent;
  int level;
  mutable bool capturing = false;  // a closure is created at this level or below
  std::vector<Name> refs;
  std::vector<std::pair<Name, Load>> loads;
  std::vector<Name> stores;

  explicit Symbols(const Symbols* p) : parent(p), level(p ? p->level + 1 : 0) {}

  bool owns(Name n) const { return std::find(refs.begin(), refs.end(), n) != refs.end(); }
  bool stored(Name n) const { return std::find(stores.begin(), stores.end(), n) != stores.end(); }
  uint16_t slotOf(Name n) const {
    return static_cast<uint16_t>(std::find(refs.begin(), refs.end(), n) - refs.begin());
  }

  const Symbols* findRef(Name n) const {
    for (const Symbols* s = this; s; s = s->parent) {
      if (s->owns(n)) return s;
    }
    return nullptr;
  }

  void setLoad(Name n, Load load) {
    for (auto& entry : loads) {
      if (entry.first == n) {
        entry.second = load;
        return;
      }
    }
    loads.emplace_back(n, load);
  }

  void defineRef(Name n, Load load) {
    if (!owns(n)) refs.push_back(n);
    setLoad(n, load);
  }

  void addStore(Name n) {
    if (!stored(n)) stores.push_back(n);
  }

  void store(Name n);

  void declareParameter(Name n) {
    addStore(n);
    defineRef(n, {SlotInitKind::Parameter});
  }

  void load(Name n) {
    if (!findRef(n)) defineRef(n, {SlotInitKind::Resolve});
  }

  // The branches are copies of this level taken before they ran (Jinja's sym.copy()), and
  // this level is unchanged since: refs and stores only grow at their ends and loads are
  // changed in place or appended, so each branch begins with this level's entries in the
  // same order, and only what follows them needs looking up. A null branch ran nothing (an
  // absent elif or else), which Jinja merges as a plain copy of this level.
  void branchUpdate(std::initializer_list<const Symbols*> branches);

  // Jinja's dump_stores: every name stored in this frame or an outer one.
  std::vector<Name> dumpStores() const;
};

}  // namespace smachac::tmpl::scopes
