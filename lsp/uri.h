// `file://` URIs ↔ paths (RFC 3986 percent-encoding; the authority must be empty or
// `localhost`). Other schemes (`untitled:`) have no path: such documents are analysed with
// their URI as their name and sub-scripts looked up from the working directory.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace smachac::lsp {

std::optional<std::string> pathFromUri(std::string_view uri);
std::string uriFromPath(std::string_view path);

}  // namespace smachac::lsp
