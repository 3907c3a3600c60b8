// Every named thing of one analysis and every place it is written: states, outcomes,
// userdata keys, template names, sub-script names and params (`[params, x]`, `[[x]]`), each
// occurrence with its location, whether it defines or refers, and the symbol it names. The
// navigation features (definition, references, hover, semantic tokens) answer from it.
//
// Rules:
//   * Names come from the module lowering made (partial when the script has errors) and, for
//     params, from the document's YAML tree; with neither, the index is empty.
//   * Locations may be in sub-scripts (states included with `script:` keep their file's
//     locations). Only the occurrences in the document itself are "in the document"; the
//     others are there for definitions and references that lead out of it.
//   * One occurrence per location: two names written at the same place (a container's input
//     key, which is both a read in its parent and a key of its own scope) are one symbol.
//   * Userdata keys follow passes/analysis/userdata_scope.h: a key lives in a container's
//     scope, where the container's and its leaves' `userdata` define it and its children's
//     input and output keys read and write it through their remapping. An unremapped key of
//     a container's interface is the same key inside and outside; a remapped one is a name of
//     the state itself, fed by the key it is remapped to. Definitions are `userdata` entries
//     and the output keys of leaves (every writer, not only the ones that reach a reader).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ir/ids.h"
#include "ir/support/source_loc.h"
#include "lsp/analysis.h"
#include "lsp/positions.h"

namespace smachac::lsp {

enum class SymbolKind : uint8_t {
  State,        ///< a state: its name, transitions to it, outcome_map children
  Outcome,      ///< an outcome of a state or container (the script's at the root)
  UserdataKey,  ///< a key of a container's userdata, or a state's own remapped name
  Template,     ///< a template name (`template:`)
  SubScript,    ///< a sub-script (`script:`)
  Param,        ///< a `params` entry, and the lookups that read it
};

/// The script key a name is written under.
enum class Site : uint8_t {
  StateName,
  Outcomes,
  TransitionOutcome,  ///< the key of a `transitions` entry
  TransitionTarget,   ///< the value of a `transitions` entry
  OutcomeMapOutcome,  ///< the key of an `outcome_map` entry
  OutcomeMapChild,
  OutcomeMapChildOutcome,
  DefaultOutcome,
  Template,
  Script,
  Userdata,
  InputKeys,
  OutputKeys,
  RemapKey,    ///< the state's own name in `remapping`
  RemapValue,  ///< the parent's name in `remapping`
  Params,
  Lookup,  ///< the `x` of `[params, x]` or `[[x]]`
};

enum class Role : uint8_t { Definition, Reference };

struct Symbol {
  SymbolKind kind = SymbolKind::State;
  std::string name;
  uint32_t file = 0;  ///< SubScript: the sub-script's file id in the analysis's sources
};

struct Occurrence {
  SourceLoc loc;  ///< the name as written
  uint32_t symbol = 0;
  Role role = Role::Reference;
  Site site = Site::StateName;
  /// The state whose script key holds the name (for a state's name, the state itself).
  ir::StateId holder;
  /// Where the name is resolved: the named state (State); the state whose outcome it is
  /// (Outcome); the container whose userdata holds the key, or the state itself for its own
  /// remapped name (UserdataKey); the state whose `params` define it (Param; the holder when
  /// none does); the holder (Template, SubScript).
  ir::StateId scope;
};

class ScriptIndex {
 public:
  explicit ScriptIndex(const Analysis& analysis);

  const Analysis& analysis() const { return analysis_; }
  /// The document's occurrence under `position`: the one whose span holds it, else the one
  /// that ends just before it (a cursor after a name); null when there is none or the
  /// position is past the end of its line.
  const Occurrence* at(Position position) const;
  /// The document's occurrences in text order; none overlap.
  std::span<const Occurrence> document() const { return {occurrences_.data(), in_document_}; }
  const Symbol& symbol(uint32_t id) const { return symbols_[id]; }
  /// Every occurrence of `symbol`: the document's in text order, then the others.
  std::vector<const Occurrence*> occurrences(uint32_t symbol) const;
  /// Where `symbol` is defined: its definitions and, for a userdata key, those of the keys
  /// that feed it. Empty for templates and sub-scripts (their files are not indexed) and for
  /// names nothing declares.
  std::vector<const Occurrence*> definitions(uint32_t symbol) const;

 private:
  void arrange();

  const Analysis& analysis_;
  std::vector<Symbol> symbols_;
  std::vector<std::vector<uint32_t>> fed_by_;  ///< per symbol
  std::vector<Occurrence> occurrences_;        ///< the document's first
  size_t in_document_ = 0;
  std::vector<std::pair<size_t, size_t>> spans_;  ///< byte spans of the document's
  std::vector<std::vector<uint32_t>> by_symbol_;  ///< occurrence indices per symbol
};

}  // namespace smachac::lsp
