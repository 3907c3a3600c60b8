// Edit-distance suggestions for unknown names.
#include "ir/support/suggest.h"

#include <algorithm>
#include <vector>

namespace smachac {

size_t editDistance(std::string_view a, std::string_view b) {
  // Optimal string alignment: insertions, deletions, substitutions and adjacent swaps.
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

namespace {

/// The edit distance within which a candidate is close to `word`.
size_t closenessLimit(std::string_view word) { return std::clamp<size_t>(word.size() / 3, 1, 3); }

}  // namespace

std::optional<std::string> closestMatch(std::string_view word,
                                        std::span<const std::string> candidates) {
  std::vector<std::string> matches = closeMatches(word, candidates, 1);
  if (matches.empty()) return std::nullopt;
  return matches.front();
}

std::vector<std::string> closeMatches(std::string_view word,
                                      std::span<const std::string> candidates, size_t limit) {
  std::vector<std::pair<size_t, const std::string*>> close;
  for (const std::string& candidate : candidates) {
    size_t distance = editDistance(word, candidate);
    if (candidate != word && distance <= closenessLimit(word))
      close.emplace_back(distance, &candidate);
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
