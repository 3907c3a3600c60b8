// Semantic tokens from the script index.
#include "lsp/features/semantic_tokens.h"

#include "lsp/features/features.h"
#include "lsp/script_index.h"

namespace smachac::lsp {
namespace {

/// Token types by SymbolKind, in its order.
constexpr const char* kTokenTypes[] = {"class", "enumMember", "variable",
                                       "type",  "namespace",  "parameter"};
constexpr uint32_t kDeclaration = 1;
constexpr uint32_t kReadonly = 2;

uint32_t modifiers(const ScriptIndex& index, const Occurrence& occurrence) {
  uint32_t bits = occurrence.role == Role::Definition ? kDeclaration : 0;
  if (index.symbol(occurrence.symbol).kind == SymbolKind::Param) bits |= kReadonly;
  return bits;
}

}  // namespace

Json semanticTokensLegend() {
  return {{"tokenTypes", kTokenTypes}, {"tokenModifiers", {"declaration", "readonly"}}};
}

Json semanticTokensFull(Workspace& workspace, const Json& params) {
  Json data = Json::array();
  const Analysis* analysis =
      workspace.analysis(params.at("textDocument").at("uri").get<std::string>());
  if (!analysis) return {{"data", data}};
  ScriptIndex index(*analysis);
  LineIndex lines = analysis->lines();
  Position previous;
  for (const Occurrence& occurrence : index.document()) {
    Range range = lines.rangeOf(occurrence.loc);
    if (range.start.line != range.end.line || range.start == range.end) continue;
    bool same_line = range.start.line == previous.line;
    data.push_back(range.start.line - previous.line);
    data.push_back(range.start.character - (same_line ? previous.character : 0));
    data.push_back(range.end.character - range.start.character);
    data.push_back(static_cast<uint32_t>(index.symbol(occurrence.symbol).kind));
    data.push_back(modifiers(index, occurrence));
    previous = range.start;
  }
  return {{"data", data}};
}

}  // namespace smachac::lsp
