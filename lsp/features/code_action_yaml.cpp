// Finding a state's mapping and adding to its lists and mappings.
#include "lsp/features/code_action_yaml.h"

#include <optional>

#include "refactor/flow_text.h"
#include "refactor/map_edits.h"
#include "refactor/script_view.h"
#include "refactor/yaml_spans.h"

namespace smachac::lsp {
namespace {

/// Deeper `states` nesting than any script has (the YAML loader bounds the tree anyway).
constexpr int kMaxDepth = 512;

bool samePlace(const SourceLoc& a, const SourceLoc& b) {
  return a.file == b.file && a.line == b.line && a.column == b.column;
}

const ir::Value* findInStates(const ir::Value& list, const SourceLoc& name, int depth);

const ir::Value* findInMapping(const ir::Value& mapping, const SourceLoc& name, int depth) {
  const ir::MapEntry* states = refactor::findKey(mapping, "states");
  return states ? findInStates(states->value, name, depth + 1) : nullptr;
}

const ir::Value* findInStates(const ir::Value& list, const SourceLoc& name, int depth) {
  if (!list.isList() || depth > kMaxDepth) return nullptr;
  for (const ir::Value& item : list.asList()) {
    const ir::Value* found = nullptr;
    if (item.isList()) {
      found = findInStates(item, name, depth + 1);
    } else if (item.isMap() && item.asMap().size() == 1) {
      const ir::MapEntry& entry = item.asMap().front();
      if (samePlace(entry.key_loc, name)) return entry.value.isMap() ? &entry.value : nullptr;
      if (entry.value.isMap()) found = findInMapping(entry.value, name, depth);
    }
    if (found) return found;
  }
  return nullptr;
}

/// Whether `prefix` is what stands before a block list item on its line: spaces, `-`, spaces.
bool isDashPrefix(std::string_view prefix) {
  size_t dash = prefix.find_first_not_of(' ');
  if (dash == std::string_view::npos || prefix[dash] != '-' || dash + 1 == prefix.size()) {
    return false;
  }
  return prefix.find_first_not_of(' ', dash + 1) == std::string_view::npos;
}

}  // namespace

const ir::Value* stateMapping(const ir::Value& root, const ir::State& state) {
  if (state.kind == ir::StateKind::Base) return root.isMap() ? &root : nullptr;
  if (root.isList()) return findInStates(root, state.name.loc, 0);  // a sub-script
  return root.isMap() ? findInMapping(root, state.name.loc, 0) : nullptr;
}

bool YamlEdit::addToList(const ir::Value& mapping, std::string_view longhand,
                         std::string_view name) {
  refactor::MapEditor maps(text_, edits_);
  std::string item = refactor::flowScalar(name);
  std::optional<size_t> index = refactor::findKeyIndex(mapping, longhand);
  if (!index) {
    bool shorthand = refactor::usesShorthand(mapping);
    maps.append(mapping, refactor::keySpelling(longhand, shorthand), "[" + item + "]");
    return true;
  }
  const ir::Value& value = mapping.asMap()[*index].value;
  if (value.isNull()) {
    maps.replaceValue(mapping, *index, "[" + item + "]");
    return true;
  }
  return value.isList() && appendListItem(value, item);
}

bool YamlEdit::addToMap(const ir::Value& mapping, std::string_view longhand, std::string_view key,
                        std::string_view value) {
  refactor::MapEditor maps(text_, edits_);
  std::string flow = refactor::flowMap({{std::string(key), std::string(value)}});
  std::optional<size_t> index = refactor::findKeyIndex(mapping, longhand);
  if (!index) {
    bool shorthand = refactor::usesShorthand(mapping);
    maps.append(mapping, refactor::keySpelling(longhand, shorthand), flow);
    return true;
  }
  const ir::Value& entries = mapping.asMap()[*index].value;
  if (entries.isNull()) {
    maps.replaceValue(mapping, *index, flow);
    return true;
  }
  if (!entries.isMap()) return false;
  maps.append(entries, refactor::flowScalar(key), value);
  return true;
}

std::string YamlEdit::result() const {
  return refactor::withLineBreaksOf(text_, edits_.render(text_.text(), {0, text_.size()}));
}

bool YamlEdit::appendListItem(const ir::Value& list, std::string_view item) {
  const ir::List& items = list.asList();
  if (refactor::isFlowCollection(text_, list)) {
    if (items.empty()) {
      edits_.insert(refactor::nodeStart(text_, list) + 1, std::string(item));
    } else {
      edits_.insert(refactor::listItemSpan(text_, list, items.back()).end,
                    ", " + std::string(item));
    }
    return true;
  }
  return !items.empty() && appendBlockItem(list, item);
}

bool YamlEdit::appendBlockItem(const ir::Value& list, std::string_view item) {
  const ir::Value& last = list.asList().back();
  size_t start = refactor::nodeStart(text_, last);
  size_t line_start = text_.lineStart(text_.lineOf(start));
  std::string prefix(text_.text().substr(line_start, start - line_start));
  if (!isDashPrefix(prefix)) return false;
  size_t at =
      text_.nextLineStart(refactor::lastLineOf(text_, refactor::listItemSpan(text_, list, last)));
  bool ends_without_break = at == text_.size() && at > 0 && text_.at(at - 1) != '\n';
  std::string line = prefix + std::string(item);
  edits_.insert(at, ends_without_break ? "\n" + line : line + "\n");
  return true;
}

}  // namespace smachac::lsp
