// The states around a completion: the chain of states from the script's root to the state the
// cursor is in (found by following the cursor's path through `states` lists in the document
// tree), and what each state declares — its outcomes, transitions, userdata keys, children —
// from the document tree, completed by the analysis's module where it has the state (states
// included from sub-scripts get their outcomes and keys from there).
// Names written at the cursor (the word being typed) are left out of what a state declares,
// so that completion offers them again while they are typed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ir/module.h"
#include "ir/value.h"
#include "lsp/yaml_context.h"

namespace smachac::lsp {

/// A name the document or the module gives, with where it is written.
struct ScopeName {
  std::string text;
  SourceLoc loc;
};

/// Where the word being typed starts (SourceLoc lines and byte columns of the document).
struct CursorSpot {
  uint32_t file = 0;
  uint32_t line = 0;
  uint32_t column = 0;

  bool at(const SourceLoc& loc) const {
    return loc.file == file && loc.line == line && loc.column == column;
  }
};

/// One state as the tree and the module know it.
class ScopeState {
 public:
  ScopeState(std::string name, const ir::Value* body, const ir::Module* module, ir::StateId id,
             CursorSpot cursor)
      : name_(std::move(name)), body_(body), module_(module), id_(id), cursor_(cursor) {}

  const std::string& name() const { return name_; }
  /// Its mapping in the document tree, or null.
  const ir::Value* body() const { return body_; }
  /// Its state in the module, or null.
  const ir::State* moduleState() const { return id_.valid() ? &module_->state(id_) : nullptr; }

  std::optional<std::string> templateName() const;
  bool isContainer() const;
  /// `key` (a core key: outcomes, input_keys, output_keys) as a list of names.
  std::vector<ScopeName> listed(std::string_view key) const;
  /// The keys of `key`'s mapping (transitions, remapping, userdata, callbacks).
  std::vector<ScopeName> mapKeys(std::string_view key) const;
  /// The entries of `key`'s mapping whose value is a name: `transitions` (outcome, target),
  /// `remapping` (key, parent's key).
  std::vector<std::pair<std::string, std::string>> mapPairs(std::string_view key) const;
  /// The keys written in the state's mapping, in longhand.
  std::vector<ScopeName> writtenKeys() const;
  /// Its states, in order.
  std::vector<ScopeState> children() const;
  /// The state `name` of item `index` of its `states`, or nullopt.
  std::optional<ScopeState> childAt(int64_t index, const std::string& name) const;

 private:
  ScopeState child(const std::string& name, const ir::Value* body) const;
  std::vector<ScopeName> fromModule(std::string_view key) const;
  std::vector<ScopeName> withoutCursor(std::vector<ScopeName> names) const;

  std::string name_;
  const ir::Value* body_;
  const ir::Module* module_;
  ir::StateId id_;
  CursorSpot cursor_;
};

/// The states from the root to the cursor's, and the path inside the last one's mapping
/// (its first key in longhand).
struct CursorScope {
  std::vector<ScopeState> chain;
  std::vector<PathSegment> rest;
  bool sub_script = false;  ///< the document is a sub-script: chain[0] is its one state
};

/// Follows `path` from the tree's root; `module` may be null.
CursorScope locateCursor(const ir::Value& root, const ir::Module* module,
                         const std::vector<PathSegment>& path, CursorSpot cursor);

/// Appends the names of `more` that `names` does not have yet.
void appendNew(std::vector<ScopeName>& names, const std::vector<ScopeName>& more);
bool contains(const std::vector<ScopeName>& names, std::string_view text);

}  // namespace smachac::lsp
