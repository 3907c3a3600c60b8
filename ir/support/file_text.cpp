// readFileText: stat, open, read in binary, and report a failure at any step as nullopt.
#include "ir/support/file_text.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace smachac {

std::optional<std::string> readFileText(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return std::move(text).str();
}

}  // namespace smachac
