// textDocument/completion: what a user typing a SMACHA script can write at the cursor
// (completion_candidates.h lists it by place). Rules of the reply:
//   * the place comes from the text up to the cursor (lsp/yaml_context.h), so a half-typed
//     line works; what states declare comes from the document tree and the module
//     (completion_scope.h);
//   * nothing in comments, in backtick code, or where no key or value is being typed;
//   * each item replaces the whole word around the cursor (a `textEdit` in UTF-16 columns);
//     a key is inserted as `key: ` unless a colon follows it already; a space is put after
//     a `:`, `,` or `-` that the cursor directly follows;
//   * items keep the candidates' order through `sortText`; the list is complete (the client
//     filters it by the word typed).
// Trigger characters (capabilities.cpp): `:`, ` `, `[`, `{`, `,`, where values, keys and
// items start.
#include <fmt/core.h>

#include "lsp/features/completion_candidates.h"
#include "lsp/features/document_tree.h"
#include "lsp/features/features.h"
#include "lsp/uri.h"
#include "lsp/yaml_context.h"

namespace smachac::lsp {
namespace {

/// Where the word being typed starts, as a SourceLoc of the document would say.
CursorSpot spotOf(const Analysis& analysis, const LineIndex& lines, size_t word_begin) {
  Position position = lines.positionOf(word_begin);
  size_t line_start = lines.offsetOf(Position{position.line, 0});
  return {analysis.file, position.line + 1, static_cast<uint32_t>(word_begin - line_start + 1)};
}

std::string insertText(const Candidate& candidate, const YamlContext& context,
                       std::string_view text) {
  std::string insert = candidate.label;
  if (context.quoted) return insert;
  bool colon_follows = context.word_end < text.size() && text[context.word_end] == ':';
  if (context.role == CursorRole::Key && !colon_follows) insert += ": ";
  char before = context.word_begin > 0 ? text[context.word_begin - 1] : '\n';
  if (before == ':' || before == ',' || before == '-') insert = " " + insert;
  return insert;
}

Json itemJson(const Candidate& candidate, size_t index, const Range& range, std::string new_text) {
  Json item = {{"label", candidate.label},
               {"kind", static_cast<int>(candidate.kind)},
               {"sortText", fmt::format("{:04}", index)},
               {"textEdit", {{"range", toJson(range)}, {"newText", std::move(new_text)}}}};
  if (!candidate.detail.empty()) item["detail"] = candidate.detail;
  if (!candidate.documentation.empty()) item["documentation"] = candidate.documentation;
  return item;
}

std::vector<Candidate> candidatesAt(const Analysis& analysis, const Settings& settings,
                                    const YamlContext& context, const LineIndex& lines) {
  DocumentTree tree(analysis);
  CursorSpot spot = spotOf(analysis, lines, context.word_begin);
  const ir::Module* module = analysis.module ? &*analysis.module : nullptr;
  CursorScope scope = locateCursor(tree.root(), module, context.path, spot);
  CompletionSources sources(settings.target, settings.template_dirs,
                            pathFromUri(analysis.uri).value_or(""), settings.script_dirs);
  return completionCandidates(scope, context.role, sources);
}

}  // namespace

Json completion(Workspace& workspace, const Json& params) {
  const Analysis* analysis =
      workspace.analysis(params.at("textDocument").at("uri").get<std::string>());
  if (!analysis) return nullptr;
  std::string_view text = analysis->text();
  LineIndex lines(text);
  YamlContext context =
      yamlContextAt(text, lines.offsetOf(positionFromJson(params.at("position"))));
  Json items = Json::array();
  if (!context.in_comment && !context.in_code && context.role != CursorRole::None) {
    std::vector<Candidate> candidates =
        candidatesAt(*analysis, workspace.settings(), context, lines);
    Range range{lines.positionOf(context.word_begin), lines.positionOf(context.word_end)};
    for (size_t i = 0; i < candidates.size(); ++i) {
      items.push_back(itemJson(candidates[i], i, range, insertText(candidates[i], context, text)));
    }
  }
  return {{"isIncomplete", false}, {"items", std::move(items)}};
}

}  // namespace smachac::lsp
