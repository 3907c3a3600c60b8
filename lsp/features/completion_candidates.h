// What completion offers at a cursor, by where the cursor is in the script (completion_scope.h):
//   * `template:` value: the templates of the target, -I directories and built-in sets, sorted
//     (Base templates at the root, the others in states; not helpers), with their summary;
//   * `transitions` keys: the state's outcomes (declared, else its template's) that have no
//     transition yet; values: the sibling states, then the container's outcomes;
//   * `outcomes` items, those not declared yet: what a container needs (targets of its states'
//     transitions that are not states, outcomes of its states without a transition), the
//     outcomes of its `outcome_map` and of its transitions, then its template's outcomes;
//   * a state's keys: `template` and `script` when it has neither, its template's variables
//     (required first), then the core keys, each one not written yet; the root: root keys;
//   * `input_keys`, `output_keys` items and `remapping` values: the userdata keys in scope
//     (the state's and its containers' userdata and input keys, its siblings' output keys
//     through their remapping, its children's); `remapping` keys: its input and output keys;
//   * `script:` value: the sub-scripts next to the document and in -S directories;
//   * `default_outcome` value: the state's outcomes.
// Candidates come in the order shown, without repeats; names already given are left out.
#pragma once

#include <string>
#include <vector>

#include "lsp/features/completion_scope.h"
#include "lsp/features/completion_sub_scripts.h"
#include "lsp/features/completion_templates.h"

namespace smachac::lsp {

/// The protocol's CompletionItemKind values completion uses.
enum class ItemKind : int {
  Function = 3,
  Variable = 6,
  Class = 7,
  Module = 9,
  Property = 10,
  Keyword = 14,
  File = 17,
  EnumMember = 20,
};

struct Candidate {
  std::string label;
  ItemKind kind = ItemKind::Keyword;
  std::string detail;
  std::string documentation;
};

/// Where completion reads what it offers; templates and sub-scripts are looked up on demand.
class CompletionSources {
 public:
  CompletionSources(const std::string& target, std::vector<std::string> template_dirs,
                    std::string document_path, std::vector<std::string> script_dirs);
  ~CompletionSources();

  TemplateLibrary& templates();
  std::optional<TemplateInfo> templateOf(const ScopeState& state);
  std::vector<SubScriptFile> subScripts() const;

 private:
  std::string target_;
  std::vector<std::string> template_dirs_;
  std::string document_path_;
  std::vector<std::string> script_dirs_;
  std::unique_ptr<TemplateLibrary> templates_;
};

/// The candidates for a cursor in `scope` with `role`.
std::vector<Candidate> completionCandidates(const CursorScope& scope, CursorRole role,
                                            CompletionSources& sources);

}  // namespace smachac::lsp
