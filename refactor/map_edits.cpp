// Mapping edits in block and flow style.
#include "refactor/map_edits.h"

#include <fmt/core.h>

namespace smachac::refactor {

void MapEditor::deleteEntries(const ir::Value& map, std::span<const size_t> indices) const {
  const ir::Map& entries = map.asMap();
  if (!isFlowCollection(text_, map)) {
    for (size_t i : indices) edits_.erase(entryLines(text_, map, entries[i]));
    return;
  }
  // Flow: runs of consecutive indices [a, b].
  for (size_t k = 0; k < indices.size();) {
    size_t a = indices[k];
    size_t b = a;
    while (k + 1 < indices.size() && indices[k + 1] == b + 1) b = indices[++k];
    ++k;
    size_t run_end = entrySpan(text_, map, entries[b]).end;
    if (b + 1 < entries.size()) {
      edits_.erase({text_.offsetOf(entries[a].key_loc), text_.offsetOf(entries[b + 1].key_loc)});
    } else if (a > 0) {
      edits_.erase({entrySpan(text_, map, entries[a - 1]).end, run_end});
    } else {
      edits_.erase({text_.offsetOf(entries[a].key_loc), run_end});
    }
  }
}

void MapEditor::deleteEntry(const ir::Value& map, size_t index) const {
  size_t one[] = {index};
  deleteEntries(map, one);
}

std::string MapEditor::blockLine(const ir::Value& map, std::string_view key,
                                 std::string_view value) const {
  size_t column = text_.columnOf(text_.offsetOf(map.asMap().front().key_loc));
  return fmt::format("{}{}: {}\n", std::string(column, ' '), key, value);
}

void MapEditor::insertBlockLine(size_t at, std::string line) const {
  if (at == text_.size() && at > 0 && text_.at(at - 1) != '\n') {
    line.pop_back();
    line.insert(line.begin(), '\n');
  }
  edits_.insert(at, std::move(line));
}

void MapEditor::append(const ir::Value& map, std::string_view key, std::string_view value) const {
  const ir::Map& entries = map.asMap();
  if (entries.empty()) {
    edits_.insert(nodeStart(text_, map) + 1, fmt::format("{}: {}", key, value));
    return;
  }
  insertAfter(map, entries.size() - 1, key, value);
}

void MapEditor::insertAfter(const ir::Value& map, size_t index, std::string_view key,
                            std::string_view value) const {
  Span entry = entrySpan(text_, map, map.asMap()[index]);
  if (isFlowCollection(text_, map)) {
    edits_.insert(entry.end, fmt::format(", {}: {}", key, value));
    return;
  }
  insertBlockLine(text_.nextLineStart(lastLineOf(text_, entry)), blockLine(map, key, value));
}

void MapEditor::insertBefore(const ir::Value& map, size_t index, std::string_view key,
                             std::string_view value) const {
  const ir::MapEntry& entry = map.asMap()[index];
  if (isFlowCollection(text_, map)) {
    edits_.insert(text_.offsetOf(entry.key_loc), fmt::format("{}: {}, ", key, value));
    return;
  }
  edits_.insert(entryLines(text_, map, entry).begin, blockLine(map, key, value));
}

void MapEditor::replaceValue(const ir::Value& map, size_t index, std::string text) const {
  Span value = entryValueSpan(text_, map, map.asMap()[index]);
  if (value.begin == value.end) text.insert(text.begin(), ' ');
  edits_.replace(value, std::move(text));
}

void EntryDeletions::apply(const MapEditor& maps) const {
  for (const auto& [map, indices] : pending_) {
    std::vector<size_t> sorted(indices.begin(), indices.end());
    maps.deleteEntries(*map, sorted);
  }
}

}  // namespace smachac::refactor
