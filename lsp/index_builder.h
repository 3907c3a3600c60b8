// Building a ScriptIndex (script_index.h): symbols are interned by what they are (a state by
// id, an outcome by state and name, a userdata key by scope and name, a param by where it is
// defined), occurrences are recorded once per location — a second name at a location already
// recorded joins its symbol (union-find) — and "fed by" links say whose definitions also
// define a userdata key. The three walks that fill it are declared here too.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "lsp/analysis.h"
#include "lsp/script_index.h"

namespace smachac::lsp {

/// What the builder made: symbols (the joined ones no longer referred to), the "fed by"
/// links of each symbol and the occurrences, all with their symbols joined.
struct IndexContents {
  std::vector<Symbol> symbols;
  std::vector<std::vector<uint32_t>> fed_by;
  std::vector<Occurrence> occurrences;
};

class IndexBuilder {
 public:
  uint32_t state(ir::StateId id, std::string_view name);
  uint32_t outcome(ir::StateId state, std::string_view name);
  /// A key of `scope`'s userdata, or of `scope`'s own names when it is a leaf.
  uint32_t key(ir::StateId scope, std::string_view name);
  uint32_t templateName(std::string_view name);
  uint32_t subScript(uint32_t file, std::string_view name);
  /// A param by the location of its `params` entry.
  uint32_t param(const SourceLoc& definition, std::string_view name);
  /// A param no `params` entry defines, read by `state`.
  uint32_t undefinedParam(ir::StateId state, std::string_view name);

  /// Records an occurrence; ignored without a location. A Definition at a location recorded
  /// as a Reference makes it a Definition.
  void add(const SourceLoc& loc, uint32_t symbol, Role role, Site site, ir::StateId holder,
           ir::StateId scope);
  void add(const ir::Name& name, uint32_t symbol, Role role, Site site, ir::StateId holder,
           ir::StateId scope) {
    add(name.loc, symbol, role, site, holder, scope);
  }
  /// The definitions of `source` also define `symbol`.
  void feed(uint32_t symbol, uint32_t source);

  IndexContents finish();

 private:
  uint32_t intern(SymbolKind kind, std::tuple<uint32_t, uint32_t, uint32_t> at,
                  std::string_view name, uint32_t file = 0);
  uint32_t root(uint32_t symbol);
  void join(uint32_t a, uint32_t b);

  std::map<std::tuple<SymbolKind, uint32_t, uint32_t, uint32_t, std::string>, uint32_t> interned_;
  std::vector<Symbol> symbols_;
  std::vector<uint32_t> parent_;  ///< union-find over symbols
  std::vector<std::pair<uint32_t, uint32_t>> feeds_;
  std::vector<Occurrence> occurrences_;
  std::map<std::tuple<uint32_t, uint32_t, uint32_t>, size_t> recorded_;  ///< by location
};

/// States, outcomes, transitions, outcome maps, templates and sub-script names.
void indexStateGraph(const ir::Module& module, IndexBuilder& builder);

/// Userdata keys, container by container (userdata, input and output keys, remapping).
void indexUserdata(const ir::Module& module, IndexBuilder& builder);

/// `params` entries and the lookups that read them, from the document's YAML tree.
void indexParams(const Analysis& analysis, IndexBuilder& builder);

}  // namespace smachac::lsp
