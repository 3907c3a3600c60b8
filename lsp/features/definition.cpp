// Go to definition, from the script index.
#include "lsp/features/definition.h"

#include <set>

#include "lsp/features/features.h"
#include "lsp/index_templates.h"
#include "lsp/uri.h"

namespace smachac::lsp {
namespace {

Json templateDefinition(const Workspace& workspace, const std::string& name) {
  std::optional<std::filesystem::path> file = TemplateFinder(workspace.settings()).file(name);
  return file ? fileStartJson(uriFromPath(file->string())) : Json(nullptr);
}

}  // namespace

Json locationJson(const Analysis& analysis, const SourceLoc& loc) {
  LineIndex lines(analysis.sources.content(loc.file));
  return {{"uri", analysis.uriOf(loc.file)}, {"range", toJson(lines.rangeOf(loc))}};
}

Json locationsJson(const Analysis& analysis, const std::vector<const Occurrence*>& occurrences) {
  Json locations = Json::array();
  std::set<std::tuple<uint32_t, uint32_t, uint32_t>> seen;
  for (const Occurrence* occurrence : occurrences) {
    const SourceLoc& loc = occurrence->loc;
    if (seen.emplace(loc.file, loc.line, loc.column).second) {
      locations.push_back(locationJson(analysis, loc));
    }
  }
  return locations;
}

Json fileStartJson(const std::string& uri) { return {{"uri", uri}, {"range", toJson(Range{})}}; }

PointedAt pointedAt(Workspace& workspace, const Json& params) {
  const Analysis* analysis =
      workspace.analysis(params.at("textDocument").at("uri").get<std::string>());
  if (!analysis) return {};
  auto index = std::make_unique<ScriptIndex>(*analysis);
  const Occurrence* occurrence = index->at(positionFromJson(params.at("position")));
  if (!occurrence) return {};
  return {std::move(index), occurrence};
}

Json definition(Workspace& workspace, const Json& params) {
  PointedAt at = pointedAt(workspace, params);
  if (!at.occurrence) return nullptr;
  const Analysis& analysis = at.index->analysis();
  const Symbol& symbol = at.index->symbol(at.occurrence->symbol);
  if (symbol.kind == SymbolKind::Template) return templateDefinition(workspace, symbol.name);
  if (symbol.kind == SymbolKind::SubScript) return fileStartJson(analysis.uriOf(symbol.file));
  Json locations = locationsJson(analysis, at.index->definitions(at.occurrence->symbol));
  return locations.empty() ? Json(nullptr) : locations;
}

}  // namespace smachac::lsp
