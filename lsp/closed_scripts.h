// The scripts of the workspace folders that the editor does not have open, as far as they
// include a sub-script the user changes: their diagnostics are published too, after the open
// documents', so that breaking a sub-script shows every script it breaks. Rules:
//   * the folders are searched once for `.yml`/`.yaml` files (hidden folders, `node_modules`
//     and `build*` folders skipped; at most kMaxFiles files), again after files change on
//     disk;
//   * a file is analysed the first time a sub-script whose name (its stem) appears in its
//     text changes; afterwards only when a file it read changes;
//   * a file whose diagnostics were published and which no longer has any gets an empty list.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lsp/analysis.h"
#include "lsp/documents.h"
#include "lsp/settings.h"

namespace smachac::lsp {

class ClosedScripts {
 public:
  static constexpr size_t kMaxFiles = 5000;

  /// The workspace folders (paths).
  void setRoots(std::vector<std::string> roots);
  /// Files changed on disk: the file list and what each file read are out of date.
  void filesChanged();

  /// The analyses of the closed scripts that read `canonical_path` (or may: see the rules),
  /// in path order.
  std::vector<std::unique_ptr<Analysis>> includersOf(const std::string& canonical_path,
                                                     const DocumentStore& documents,
                                                     const Settings& settings);

 private:
  const std::vector<std::string>& files();
  bool mayRead(const std::string& file, const std::string& canonical_path);

  std::vector<std::string> roots_;
  std::optional<std::vector<std::string>> files_;
  std::map<std::string, std::set<std::string>> reads_;  ///< file → the files it read
};

}  // namespace smachac::lsp
