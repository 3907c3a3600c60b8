// Building the index, ordering it for position lookups, and following its links.
#include "lsp/script_index.h"

#include <algorithm>
#include <set>

#include "lsp/index_builder.h"

namespace smachac::lsp {
namespace {

bool before(const Occurrence& a, const Occurrence& b) {
  return std::tie(a.loc.file, a.loc.line, a.loc.column) <
         std::tie(b.loc.file, b.loc.line, b.loc.column);
}

}  // namespace

ScriptIndex::ScriptIndex(const Analysis& analysis) : analysis_(analysis) {
  if (analysis.module) {
    IndexBuilder builder;
    indexStateGraph(*analysis.module, builder);
    indexUserdata(*analysis.module, builder);
    indexParams(analysis, builder);
    IndexContents contents = builder.finish();
    symbols_ = std::move(contents.symbols);
    fed_by_ = std::move(contents.fed_by);
    occurrences_ = std::move(contents.occurrences);
  }
  arrange();
}

/// The document's occurrences first, in text order and without overlaps, then the others;
/// the byte spans of the document's, and each symbol's occurrences.
void ScriptIndex::arrange() {
  auto others =
      std::stable_partition(occurrences_.begin(), occurrences_.end(),
                            [&](const Occurrence& o) { return o.loc.file == analysis_.file; });
  std::stable_sort(occurrences_.begin(), others, before);
  std::stable_sort(others, occurrences_.end(), before);
  LineIndex lines(analysis_.text());
  std::vector<Occurrence> arranged;
  for (auto it = occurrences_.begin(); it != others; ++it) {
    size_t start = lines.offsetOf(it->loc);
    size_t end = lines.offsetOf(lines.rangeOf(it->loc).end);
    if (!spans_.empty() && start < spans_.back().second) continue;
    spans_.emplace_back(start, end);
    arranged.push_back(*it);
  }
  in_document_ = arranged.size();
  arranged.insert(arranged.end(), others, occurrences_.end());
  occurrences_ = std::move(arranged);
  by_symbol_.resize(symbols_.size());
  for (uint32_t i = 0; i < occurrences_.size(); ++i) {
    by_symbol_[occurrences_[i].symbol].push_back(i);
  }
}

const Occurrence* ScriptIndex::at(Position position) const {
  LineIndex lines(analysis_.text());
  size_t offset = lines.offsetOf(position);
  if (lines.positionOf(offset) != position) return nullptr;  // past the end of its line
  auto after = std::upper_bound(spans_.begin(), spans_.end(), offset,
                                [](size_t value, const auto& span) { return value < span.first; });
  if (after == spans_.begin()) return nullptr;
  size_t i = static_cast<size_t>(after - spans_.begin()) - 1;
  return offset <= spans_[i].second ? &occurrences_[i] : nullptr;
}

std::vector<const Occurrence*> ScriptIndex::occurrences(uint32_t symbol) const {
  std::vector<const Occurrence*> found;
  if (symbol >= by_symbol_.size()) return found;
  for (uint32_t i : by_symbol_[symbol]) found.push_back(&occurrences_[i]);
  return found;
}

std::vector<const Occurrence*> ScriptIndex::definitions(uint32_t symbol) const {
  std::vector<const Occurrence*> found;
  std::set<uint32_t> seen;
  std::vector<uint32_t> pending = {symbol};
  while (!pending.empty() && symbol < by_symbol_.size()) {
    uint32_t next = pending.back();
    pending.pop_back();
    if (!seen.insert(next).second) continue;
    for (const Occurrence* occurrence : occurrences(next)) {
      if (occurrence->role == Role::Definition) found.push_back(occurrence);
    }
    pending.insert(pending.end(), fed_by_[next].rbegin(), fed_by_[next].rend());
  }
  return found;
}

}  // namespace smachac::lsp
