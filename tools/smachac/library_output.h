// Where `-emit=library` writes its header/source pair, from -o:
//   -o DIR/ or -o DIR (an existing directory)  DIR/<script name>.h and DIR/<script name>.cpp
//   -o PATH/NAME.cpp (or .cc, .cxx)              PATH/NAME.cpp and PATH/NAME.h next to it
// The declarations go into a namespace named after the file name's stem, mangled into a C++
// identifier: other characters become `_`, runs of `_` one `_`, a name starting with a digit
// or `_` gets `sm` in front, and a keyword or a name the generated code uses (`rt`, `std`,
// `smachac`, `main`) gets `_` after it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "backends/targets.h"

namespace smachac::driver {

/// What -o says before the script is compiled: the directory, and the source's file name when
/// -o names it (empty: named after the script).
struct LibraryOutput {
  std::string dir;
  std::string source;
};

/// The pair's place from -o, or a usage error message.
std::variant<LibraryOutput, std::string> libraryOutput(const std::string& output);

/// The file names and namespace; `script_name` names the files when -o is a directory.
backends::LibraryNames libraryNames(const LibraryOutput& output, std::string_view script_name);

/// `stem` as a C++ namespace name (see above).
std::string namespaceName(std::string_view stem);

}  // namespace smachac::driver
