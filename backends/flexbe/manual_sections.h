// FlexBE's [MANUAL_*] sections: the text between `# [MANUAL_X]` and
// `# [/MANUAL_X]` belongs to the user and survives regeneration byte for byte.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace smachac::backends::flexbe {

/// `generated` with the contents of each manual section that `existing` also has replaced by
/// the existing contents (from after the opening tag's line to the start of the closing tag's
/// line). nullopt when `existing` has an opening tag without its closing tag, or tags out of
/// order (FlexBE's extract_manual raises on these).
std::optional<std::string> keepManualSections(std::string_view generated,
                                              std::string_view existing);

}  // namespace smachac::backends::flexbe
