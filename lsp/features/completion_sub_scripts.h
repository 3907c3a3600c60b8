// The sub-scripts a `script:` key can name, found where the frontend looks for them
// (frontend/sub_scripts.h): in the directory of the including document, then in each -S
// directory. A sub-script is named as scripts write it: its path relative to the directory,
// without `.yml` (`greet`, `sub/greet`). Rules:
//   * `.yml` files in a directory and in its subdirectories one level down, hidden ones
//     skipped, the document itself skipped;
//   * only files that look like a sub-script: their first line that is not blank or a comment
//     starts a list item (`- NAME:`);
//   * a name found in an earlier directory hides the same name in a later one (as the
//     frontend would read the first); at most kMaxSubScriptFiles files are looked at per
//     directory, so a huge directory cannot stall the editor.
#pragma once

#include <string>
#include <vector>

namespace smachac::lsp {

inline constexpr size_t kMaxSubScriptFiles = 2000;

struct SubScriptFile {
  std::string name;  ///< as a script writes it: `sub/greet`
  /// The file: relative to the document's directory, or in the -S directory as given.
  std::string path;
};

/// The sub-scripts the document `document_path` can include (an empty path: a document that
/// is not a file, whose sub-scripts are looked for from the working directory), sorted by name.
std::vector<SubScriptFile> findSubScripts(const std::string& document_path,
                                          const std::vector<std::string>& script_dirs);

}  // namespace smachac::lsp
