// Edits of one YAML mapping of the script, in the style it is written in. Rules:
//   * block mapping: an entry is whole lines (with the comment lines right above it); a new
//     entry is a new line at the column of the existing keys
//   * flow mapping: a run of deleted entries goes with one separating comma; a new entry is
//     `key: value` with `, ` on the side that has a neighbour
//   * deleting every entry of a flow mapping leaves `{}`; callers delete the key instead
#pragma once

#include <map>
#include <set>
#include <span>
#include <string_view>

#include "ir/value.h"
#include "refactor/text_edits.h"
#include "refactor/yaml_spans.h"

namespace smachac::refactor {

class MapEditor {
 public:
  MapEditor(const SourceText& text, EditList& edits) : text_(text), edits_(edits) {}

  /// Deletes the entries at `indices` (ascending) of `map`.
  void deleteEntries(const ir::Value& map, std::span<const size_t> indices) const;
  void deleteEntry(const ir::Value& map, size_t index) const;

  /// Adds `key: value` after the last entry.
  void append(const ir::Value& map, std::string_view key, std::string_view value) const;
  /// Adds `key: value` right after / before entry `index`.
  void insertAfter(const ir::Value& map, size_t index, std::string_view key,
                   std::string_view value) const;
  void insertBefore(const ir::Value& map, size_t index, std::string_view key,
                    std::string_view value) const;

  /// Replaces the value of entry `index` (its text, not the key).
  void replaceValue(const ir::Value& map, size_t index, std::string text) const;

 private:
  std::string blockLine(const ir::Value& map, std::string_view key, std::string_view value) const;
  void insertBlockLine(size_t at, std::string line) const;

  const SourceText& text_;
  EditList& edits_;
};

/// Entry deletions collected by several steps and applied once per mapping, so that the
/// runs of a flow mapping share their commas correctly.
class EntryDeletions {
 public:
  void add(const ir::Value& map, size_t index) { pending_[&map].insert(index); }
  void add(const ir::Value& map, std::span<const size_t> indices) {
    pending_[&map].insert(indices.begin(), indices.end());
  }
  void apply(const MapEditor& maps) const;

 private:
  std::map<const ir::Value*, std::set<size_t>> pending_;
};

}  // namespace smachac::refactor
