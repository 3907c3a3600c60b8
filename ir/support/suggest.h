// "Did you mean" suggestions: the closest candidate by edit distance, if close enough.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace smachac {

/// While one lives on a thread, the searches of closeMatches there share its budget of name
/// comparisons, and once it is spent they find nothing: a script with thousands of unknown
/// names among thousands of states would otherwise compare them all pairwise (minutes at
/// 100,000 states; clang limits its spelling corrections alike). A search is made whole or not
/// at all, so the output stays deterministic. Nested budgets: the innermost counts.
class SuggestionBudget {
 public:
  static constexpr size_t kDefaultComparisons = 10'000'000;
  explicit SuggestionBudget(size_t comparisons = kDefaultComparisons);
  ~SuggestionBudget();
  SuggestionBudget(const SuggestionBudget&) = delete;
  SuggestionBudget& operator=(const SuggestionBudget&) = delete;

  /// Takes `comparisons` from the thread's budget; false (and nothing taken) when it has
  /// fewer left. Always true on a thread without a budget.
  static bool spend(size_t comparisons);

 private:
  size_t left_;
  SuggestionBudget* outer_;
};

/// Edit distance (insert, delete, substitute, swap adjacent), byte-wise.
size_t editDistance(std::string_view a, std::string_view b);

/// The candidate closest to `word` when it is within about a third of the word's length
/// (at least 1, at most 3 edits); ties go to the earliest candidate. Never `word` itself.
std::optional<std::string> closestMatch(std::string_view word,
                                        std::span<const std::string> candidates);

/// Every candidate as close to `word` as closestMatch requires, closest first (ties in
/// candidate order), at most `limit` of them; none when the thread's SuggestionBudget cannot
/// pay for comparing `word` with every candidate.
std::vector<std::string> closeMatches(std::string_view word,
                                      std::span<const std::string> candidates, size_t limit);

/// "`a`, `b`, `c`": names in backticks, as diagnostic messages list them.
std::string quotedList(std::span<const std::string> names);

/// "; did you mean `x`?" or "" — the suffix used by diagnostic messages.
std::string didYouMean(std::string_view word, std::span<const std::string> candidates);
/// The same suffix for a match already found (closestMatch), which is also the diagnostic's
/// fix-it (DiagnosticEmitter::fixIt).
std::string didYouMean(const std::optional<std::string>& match);

}  // namespace smachac
