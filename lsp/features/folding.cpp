// textDocument/foldingRange: what an editor can fold in a script.
//   * every mapping entry and list item whose value spans several lines folds from its first
//     line to the last line of its value: each state (its `- NAME:` line to the end of its
//     body), `states`, `userdata`, `transitions`... written in block or flow style;
//   * every run of two or more comment lines folds, with kind `comment`;
//   * one range per first line (the outermost), sorted by line; the whole document does not
//     fold.
// Ranges come from the document tree (document_tree.h): the parsed YAML, else the tolerant
// reading of a text that does not parse, which follows its indentation.
#include <map>
#include <string>

#include "lsp/features/document_tree.h"
#include "lsp/features/features.h"

namespace smachac::lsp {
namespace {

struct Fold {
  uint32_t end_line = 0;
  bool comment = false;
};

class FoldCollector {
 public:
  explicit FoldCollector(std::string_view text) : text_(text), lines_(text) {}

  void addNodes(const ir::Value& node) {
    if (node.isMap()) {
      for (const ir::MapEntry& entry : node.asMap()) addSpan(entry.key_loc, entry.value);
    } else if (node.isList()) {
      for (const ir::Value& item : node.asList()) addSpan(item.loc, item);
    }
  }

  void addComments() {
    uint32_t run_start = 0;
    uint32_t run_length = 0;
    for (uint32_t line = 0; line <= lines_.lineCount(); ++line) {
      if (line < lines_.lineCount() && isComment(lines_.lineText(line))) {
        if (run_length++ == 0) run_start = line;
        continue;
      }
      if (run_length >= 2) add(run_start, run_start + run_length - 1, true);
      run_length = 0;
    }
  }

  Json ranges() const {
    Json json = Json::array();
    for (const auto& [start, fold] : folds_) {
      Json range = {{"startLine", start}, {"endLine", fold.end_line}};
      if (fold.comment) range["kind"] = "comment";
      json.push_back(std::move(range));
    }
    return json;
  }

 private:
  /// A node that starts on the line of `first` folds to its last line; then its children.
  void addSpan(const SourceLoc& first, const ir::Value& node) {
    if (!node.isMap() && !node.isList()) return;
    if (first.hasLine()) {
      Position end = lines_.positionOf(nodeEnd(node, lines_, text_));
      add(first.line - 1, end.line, false);
    }
    addNodes(node);
  }

  void add(uint32_t start, uint32_t end, bool comment) {
    if (end <= start) return;
    auto [it, inserted] = folds_.try_emplace(start, Fold{end, comment});
    if (!inserted && it->second.end_line < end) it->second = Fold{end, comment};
  }

  static bool isComment(std::string_view line) {
    size_t first = line.find_first_not_of(" \t");
    return first != std::string_view::npos && line[first] == '#';
  }

  std::string_view text_;
  LineIndex lines_;
  std::map<uint32_t, Fold> folds_;  ///< by first line
};

}  // namespace

Json foldingRange(Workspace& workspace, const Json& params) {
  const Analysis* analysis =
      workspace.analysis(params.at("textDocument").at("uri").get<std::string>());
  if (!analysis) return nullptr;
  DocumentTree tree(*analysis);
  FoldCollector folds(analysis->text());
  folds.addNodes(tree.root());
  folds.addComments();
  return folds.ranges();
}

}  // namespace smachac::lsp
