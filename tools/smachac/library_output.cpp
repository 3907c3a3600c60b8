// The -o rules and names of `-emit=library`.
#include "tools/smachac/library_output.h"

#include <algorithm>
#include <array>
#include <filesystem>

#include "ir/support/identifiers.h"
#include "ir/support/python_text.h"

namespace smachac::driver {
namespace {

namespace fs = std::filesystem;

constexpr std::array<std::string_view, 3> kSourceExtensions = {".cpp", ".cc", ".cxx"};
constexpr std::array<std::string_view, 4> kTakenNames = {"rt", "std", "smachac", "main"};

bool isSourceFile(const fs::path& path) {
  std::string extension = path.extension().string();
  return path.stem() != "" && std::find(kSourceExtensions.begin(), kSourceExtensions.end(),
                                        extension) != kSourceExtensions.end();
}

/// A file name that an `#include "..."` line can hold as written.
bool isIncludable(std::string_view name) {
  return std::none_of(name.begin(), name.end(), [](char c) {
    return c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20;
  });
}

}  // namespace

std::variant<LibraryOutput, std::string> libraryOutput(const std::string& output) {
  if (output.empty() || output == "-") {
    return std::string(
        "-emit=library writes two files: -o must name a directory or the .cpp file to write");
  }
  std::error_code error;
  if (output.ends_with('/') || fs::is_directory(output, error)) return LibraryOutput{output, ""};
  fs::path path(output);
  if (!isSourceFile(path)) {
    return "-emit=library: -o `" + output +
           "` is neither a directory nor a source file (.cpp, .cc, .cxx)";
  }
  if (!isIncludable(path.filename().string())) {
    return "-emit=library: the file name `" + path.filename().string() +
           "` cannot be written in an #include line";
  }
  std::string dir = path.parent_path().string();
  return LibraryOutput{dir.empty() ? "." : dir, path.filename().string()};
}

backends::LibraryNames libraryNames(const LibraryOutput& output, std::string_view script_name) {
  std::string source = output.source.empty() ? std::string(script_name) + ".cpp" : output.source;
  std::string stem = fs::path(source).stem().string();
  return {source, stem + ".h", namespaceName(stem)};
}

std::string namespaceName(std::string_view stem) {
  std::string name;
  for (char c : stem) {
    char mapped = isIdentifierChar(c) ? c : '_';
    if (mapped == '_' && name.ends_with('_')) continue;
    name += mapped;
  }
  if (name.empty() || name[0] == '_') name = "sm" + name;
  if (name[0] >= '0' && name[0] <= '9') name = "sm_" + name;
  bool taken = std::find(kTakenNames.begin(), kTakenNames.end(), name) != kTakenNames.end();
  if (taken || identifierProblem(name, IdentifierRules::Cpp)) name += "_";
  return name;
}

}  // namespace smachac::driver
