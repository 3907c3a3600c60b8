// Edit-distance suggestions for unknown names.
#include "ir/support/suggest.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace smachac {

namespace {

thread_local SuggestionBudget* t_budget = nullptr;

/// Three rows of the optimal-string-alignment table, kept between candidates (a suggestion
/// compares one word with every name in scope: thousands in a big script).
struct DistanceRows {
  std::vector<size_t> before_last, last, current;
};

/// The edit distance of `a` and `b` when it is at most `bound`, else a number above `bound`.
/// Row by row: once a row holds nothing within the bound, no later row can (a cell is at least
/// a cell of the row above: a swap's d[i-2][j-2] + 1 is at least d[i-1][j-1]).
size_t distanceWithin(std::string_view a, std::string_view b, size_t bound, DistanceRows& rows) {
  auto& [before_last, last, current] = rows;
  last.resize(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) last[j] = j;
  before_last.assign(b.size() + 1, 0);
  current.resize(b.size() + 1);
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    size_t row_min = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      current[j] = std::min({last[j] + 1, current[j - 1] + 1, last[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        current[j] = std::min(current[j], before_last[j - 2] + 1);
      }
      row_min = std::min(row_min, current[j]);
    }
    if (row_min > bound) return bound + 1;
    std::swap(before_last, last);
    std::swap(last, current);
  }
  return last[b.size()];
}

/// The edit distance within which a candidate is close to `word`.
size_t closenessLimit(std::string_view word) { return std::clamp<size_t>(word.size() / 3, 1, 3); }

}  // namespace

SuggestionBudget::SuggestionBudget(size_t comparisons) : left_(comparisons), outer_(t_budget) {
  t_budget = this;
}

SuggestionBudget::~SuggestionBudget() { t_budget = outer_; }

bool SuggestionBudget::spend(size_t comparisons) {
  if (!t_budget) return true;
  if (t_budget->left_ < comparisons) return false;
  t_budget->left_ -= comparisons;
  return true;
}

size_t editDistance(std::string_view a, std::string_view b) {
  DistanceRows rows;
  return distanceWithin(a, b, a.size() + b.size(), rows);
}

std::optional<std::string> closestMatch(std::string_view word,
                                        std::span<const std::string> candidates) {
  std::vector<std::string> matches = closeMatches(word, candidates, 1);
  if (matches.empty()) return std::nullopt;
  return matches.front();
}

std::vector<std::string> closeMatches(std::string_view word,
                                      std::span<const std::string> candidates, size_t limit) {
  if (!SuggestionBudget::spend(candidates.size())) return {};
  const size_t within = closenessLimit(word);
  std::vector<std::pair<size_t, const std::string*>> close;
  DistanceRows rows;
  for (const std::string& candidate : candidates) {
    // Each byte of length between them takes an edit: most candidates end here.
    const size_t length_gap =
        std::max(word.size(), candidate.size()) - std::min(word.size(), candidate.size());
    if (length_gap > within || candidate == word) continue;
    const size_t distance = distanceWithin(word, candidate, within, rows);
    if (distance <= within) close.emplace_back(distance, &candidate);
  }
  std::stable_sort(close.begin(), close.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> matches;
  for (size_t i = 0; i < close.size() && i < limit; ++i) matches.push_back(*close[i].second);
  return matches;
}

std::string quotedList(std::span<const std::string> names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "`" : ", `") + name + "`";
  return list;
}

std::string didYouMean(std::string_view word, std::span<const std::string> candidates) {
  return didYouMean(closestMatch(word, candidates));
}

std::string didYouMean(const std::optional<std::string>& match) {
  return match ? "; did you mean `" + *match + "`?" : std::string();
}

}  // namespace smachac
