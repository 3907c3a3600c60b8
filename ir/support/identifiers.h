// Identifier rules of the output targets, for names that become code identifiers:
//   smach, smach_ros, flexbe  Python 3: ASCII letters, digits and `_`, not starting with a
//                             digit, not a keyword (non-ASCII identifiers are not accepted:
//                             their case folding and normalisation differ between targets)
//   cpp                       C++: the same character rule, not a keyword, and not a reserved
//                             name (containing `__`, or `_` followed by a capital letter)
//   ir, json, dot, yaml, ...  no rule: names are only ever printed as strings
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace smachac {

enum class IdentifierRules { None, Python, Cpp };

IdentifierRules identifierRules(std::string_view target);

/// "Python" or "C++".
std::string_view rulesName(IdentifierRules rules);

/// ASCII letters, digits and `_`, not starting with a digit, not empty.
bool isAsciiIdentifier(std::string_view text);

/// Why `text` is not an identifier under `rules`, as a predicate ("starts with a digit",
/// "contains `-`", "is a keyword", ...), or nullopt when it is one.
std::optional<std::string> identifierProblem(std::string_view text, IdentifierRules rules);

/// ASCII lower case, as SMACHA's `lower` filter does for variable names.
std::string asciiLower(std::string_view text);

}  // namespace smachac
