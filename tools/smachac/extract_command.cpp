// `smachac extract SCRIPT STATE [-sub sub.yml] [-sup super.yml] [-S dir]`: splits a root
// state into a sub-script and a super-script (refactor/extract.h has the
// rules). Outputs default to SMACHA's `smacha_extract_sub_script_output.yml` and
// `smacha_extract_super_script_output.yml`; the super-script names the sub-script by its
// file name without extension (with `-sub -`, by the state's name in lowercase). `-` writes
// to standard output (the sub-script first). The input is never written; if the second
// file cannot be written, the first is restored, so a failed run changes nothing.
#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>

#include "ir/support/file_text.h"
#include "refactor/extract.h"
#include "tools/smachac/output.h"
#include "tools/smachac/script_tool.h"

namespace smachac::driver {
namespace {

namespace fs = std::filesystem;

struct ExtractOptions {
  std::string script;
  std::string state;
  std::string sub = "smacha_extract_sub_script_output.yml";
  std::string super = "smacha_extract_super_script_output.yml";
};

void setUp(CLI::App& app, ExtractOptions& o) {
  app.add_option("script", o.script, "the script")->required()->type_name("SCRIPT");
  app.add_option("state", o.state, "the root state to extract")->required()->type_name("STATE");
  app.add_option("--sub", o.sub,
                 "sub-script output (default smacha_extract_sub_script_output.yml)");
  app.add_option("--sup", o.super,
                 "super-script output (default smacha_extract_super_script_output.yml)");
}

bool samePath(const std::string& a, const std::string& b) {
  if (a == "-" || b == "-") return false;
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

std::optional<std::string> checkPaths(const ExtractOptions& o) {
  for (const std::string* out : {&o.sub, &o.super}) {
    if (samePath(*out, o.script)) return fmt::format("`{}` is the input script", *out);
  }
  if (samePath(o.sub, o.super)) return "the sub-script and the super-script are the same file";
  return std::nullopt;
}

std::string subScriptName(const ExtractOptions& o) {
  std::string name = o.sub == "-" ? o.state : fs::path(o.sub).stem().string();
  if (o.sub == "-") {
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  }
  return name;
}

std::optional<std::string> readExisting(const std::string& path) {
  if (path == "-") return std::nullopt;
  return readFileText(path);
}

/// Writes both files, or neither: the first is restored when the second fails.
std::optional<std::string> writeBoth(const ExtractOptions& o, const refactor::ExtractResult& r) {
  std::optional<std::string> previous = readExisting(o.sub);
  if (std::optional<std::string> error = writeFileAtomically(o.sub, r.sub_script)) return error;
  std::optional<std::string> error = writeFileAtomically(o.super, r.super_script);
  if (error && o.sub != "-") {
    std::error_code ec;
    if (previous) {
      writeFileAtomically(o.sub, *previous);
    } else {
      fs::remove(o.sub, ec);
    }
  }
  return error;
}

}  // namespace

int runExtract(const Args& args) {
  ScriptTool tool("extract",
                  "smachac extract: split a root state into a sub-script and a "
                  "super-script");
  ExtractOptions o;
  setUp(tool.app(), o);
  if (std::optional<int> code = tool.start(args, [&] { return checkPaths(o); })) return *code;
  std::optional<refactor::ScriptView> script = tool.load(o.script);
  std::optional<refactor::ExtractResult> result;
  if (script) {
    result = refactor::extract(*script, o.state, subScriptName(o), tool.session().diags());
  }
  if (std::optional<int> code = tool.report(result.has_value())) return *code;
  if (std::optional<std::string> error = writeBoth(o, *result)) {
    std::cerr << "smachac: error: " << *error << "\n";
    return kExitUsageError;
  }
  return kExitOk;
}

}  // namespace smachac::driver
