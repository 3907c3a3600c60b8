// Command-line normalisation.
#include "tools/smachac/args.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace smachac::driver {
namespace {

constexpr std::array<std::string_view, 20> kLongOptions = {
    // the driver's options
    "target", "fsyntax-only", "fdiagnostics-format", "list-passes", "print-ir-after",
    "disable-pass", "emit", "flexbe-ros", "version", "help", "list-targets", "list-warnings",
    // the subcommands' options
    "sub", "sup", "context", "block", "builtin-set", "no-ansi", "skip-block", "default-target"};

bool isLongOption(std::string_view arg) {
  if (arg.size() < 3 || arg[0] != '-' || arg[1] == '-') return false;
  std::string_view name = arg.substr(1, arg.find('=') - 1);
  return std::find(kLongOptions.begin(), kLongOptions.end(), name) != kLongOptions.end();
}

}  // namespace

std::vector<std::string> normalizeArgs(std::vector<std::string> args) {
  for (std::string& arg : args) {
    if (arg == "--") break;
    if (isLongOption(arg)) arg.insert(arg.begin(), '-');
  }
  return args;
}

std::vector<std::string> takeWarningFlags(std::vector<std::string>& args) {
  std::vector<std::string> flags;
  std::vector<std::string> rest;
  bool after_dashdash = false;
  for (std::string& arg : args) {
    after_dashdash = after_dashdash || arg == "--";
    if (!after_dashdash && arg.size() > 2 && arg.starts_with("-W")) {
      flags.push_back(std::move(arg));
    } else {
      rest.push_back(std::move(arg));
    }
  }
  args = std::move(rest);
  return flags;
}

}  // namespace smachac::driver
