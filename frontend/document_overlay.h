// Texts that stand for files: an editor's documents, open and perhaps unsaved, keyed by their
// canonical path. A sub-script found in the overlay is read from it instead of the disk.
#pragma once

#include <functional>
#include <map>
#include <string>

namespace smachac::frontend {

using DocumentOverlay = std::map<std::string, std::string, std::less<>>;

}  // namespace smachac::frontend
