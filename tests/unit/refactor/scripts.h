// Test helper: scripts written to a temporary directory, loaded as the tools load them, and
// linted as `smachac lint` does (frontend and every check).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"
#include "refactor/contain.h"
#include "refactor/extract.h"

namespace smachac::refactor::testing {

/// A temporary directory that is removed with the object.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  /// Writes `text` to `name` in the directory; returns its path.
  std::string write(const std::string& name, const std::string& text) const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// A script loaded for the tools, with its diagnostics.
struct Loaded {
  SourceManager sources;
  DiagnosticEmitter diags;
  std::optional<ScriptView> script;
  /// The kebab-case kinds of the diagnostics, in order.
  std::vector<std::string> kinds() const;
};

std::unique_ptr<Loaded> load(const std::string& path, std::vector<std::string> script_dirs = {});

/// contain on a script file; nullopt on errors (their kinds in `kinds` when given).
std::optional<std::string> containFile(const std::string& path, const ContainRequest& request,
                                       std::vector<std::string>* kinds = nullptr,
                                       std::vector<std::string> script_dirs = {});

/// What `smachac lint` reports for a script file.
struct LintResult {
  size_t errors = 0;
  size_t warnings = 0;
  std::vector<std::string> kinds;
};
LintResult lint(const std::string& path, std::vector<std::string> script_dirs = {});

}  // namespace smachac::refactor::testing
