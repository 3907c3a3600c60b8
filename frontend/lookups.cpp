// Params inheritance, lookups and string constructs.
#include "frontend/lookups.h"

#include <fmt/core.h>

#include <algorithm>

#include "frontend/scalar.h"
#include "ir/python_text.h"

namespace smachac::frontend {
namespace {

using ir::Value;

/// Views of the list's strings: every list value of every state is tried as a lookup.
struct LookupKey {
  std::string_view key;
  std::optional<std::string_view> entry;
};

/// Reads `[k]`, `[k, j]` or `[[x]]` (→ params, x). nullopt when the list is none of them.
std::optional<LookupKey> lookupKey(const Value& list) {
  if (!list.isList()) return std::nullopt;
  const ir::List& items = list.asList();
  if (items.size() == 1 && items[0].isList() && items[0].asList().size() == 1 &&
      items[0].asList()[0].isString()) {
    return LookupKey{"params", std::string_view(items[0].asList()[0].asString())};
  }
  if (items.size() == 1 && items[0].isString()) return LookupKey{items[0].asString(), {}};
  if (items.size() == 2 && items[0].isString() && items[1].isString()) {
    return LookupKey{items[0].asString(), std::string_view(items[1].asString())};
  }
  return std::nullopt;
}

std::string spell(const LookupKey& k) {
  return k.entry ? fmt::format("[{}, {}]", k.key, *k.entry) : fmt::format("[{}]", k.key);
}

enum class Outcome { Resolved, NotALookup, FailedParams };

struct Lookup {
  Outcome outcome = Outcome::NotALookup;
  Value value;
  std::string reason;
};

Lookup tryLookup(const Value& vars, const Value& list) {
  std::optional<LookupKey> k = lookupKey(list);
  if (!k) return {};
  const Value* base = vars.find(k->key);
  bool params = k->key == "params";
  if (!base) {
    if (!params) return {};
    return {Outcome::FailedParams, {}, "the state has no `params`"};
  }
  if (!k->entry) return {Outcome::Resolved, *base, {}};
  const Value* entry = base->find(*k->entry);
  if (entry) return {Outcome::Resolved, *entry, {}};
  if (!params) return {};
  return {Outcome::FailedParams, {}, fmt::format("`params` has no `{}`", *k->entry)};
}

class Resolver {
 public:
  Resolver(Value& vars, DiagnosticEmitter& diags) : vars_(vars), diags_(diags) {}

  void run() {
    for (ir::MapEntry& entry : vars_.asMap()) {
      if (entry.key == "states") continue;
      if (entry.value.isList()) {
        resolve(entry.value);
      } else if (entry.value.isMap()) {
        for (ir::MapEntry& inner : entry.value.asMap()) {
          if (inner.value.isList()) resolve(inner.value);
        }
      }
    }
  }

 private:
  void resolve(Value& value) {
    Lookup lookup = tryLookup(vars_, value);
    if (lookup.outcome == Outcome::Resolved) {
      SourceLoc use = value.loc;
      value = std::move(lookup.value);
      value.loc = use;
      return;
    }
    if (lookup.outcome == Outcome::FailedParams) {
      report(value, lookup.reason);
      return;
    }
    construct(value);
  }

  void report(const Value& list, const std::string& reason) {
    diags_.emit<DiagKind::UnresolvedLookup>(list.loc, spell(*lookupKey(list)), reason);
  }

  /// A string construct: joins the parts when at least one is a lookup.
  void construct(Value& value) {
    const ir::List& parts = value.asList();
    if (std::none_of(parts.begin(), parts.end(), [](const Value& p) { return p.isList(); })) {
      return;  // only a list part can be a lookup
    }
    std::string text;
    bool had_lookup = false;
    for (const Value& part : value.asList()) {
      if (part.isString()) {
        text += part.asString();
        continue;
      }
      if (!part.isList()) {
        text += ir::pythonStr(part);
        continue;
      }
      Lookup lookup = tryLookup(vars_, part);
      if (lookup.outcome == Outcome::FailedParams) report(part, lookup.reason);
      if (lookup.outcome != Outcome::Resolved) return;
      text += ir::pythonStr(lookup.value);
      had_lookup = true;
    }
    if (had_lookup) value = textValue(text, value.loc);
  }

  Value& vars_;
  DiagnosticEmitter& diags_;
};

}  // namespace

void inheritParams(Value& state_vars, const std::optional<Value>& inherited) {
  if (!inherited || !inherited->isMap()) return;
  Value* own = state_vars.find("params");
  if (!own) {
    state_vars.asMap().push_back({"params", inherited->loc, *inherited});
    return;
  }
  if (!own->isMap()) return;
  for (const ir::MapEntry& entry : inherited->asMap()) {
    if (!own->find(entry.key)) own->asMap().push_back(entry);
  }
}

void resolveLookups(Value& state_vars, DiagnosticEmitter& diags) {
  if (state_vars.isMap()) Resolver(state_vars, diags).run();
}

}  // namespace smachac::frontend
