// "Did you mean" suggestions: the closest candidate by edit distance, if close enough.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace smachac {

/// Edit distance (insert, delete, substitute, swap adjacent), byte-wise.
size_t editDistance(std::string_view a, std::string_view b);

/// The candidate closest to `word` when it is within about a third of the word's length
/// (at least 1, at most 3 edits); ties go to the earliest candidate. Never `word` itself.
std::optional<std::string> closestMatch(std::string_view word,
                                        std::span<const std::string> candidates);

/// Every candidate as close to `word` as closestMatch requires, closest first (ties in
/// candidate order), at most `limit` of them.
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
