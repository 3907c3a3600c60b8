// Interning symbols, recording occurrences once per location, joining symbols.
#include "lsp/index_builder.h"

namespace smachac::lsp {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

}  // namespace

uint32_t IndexBuilder::state(ir::StateId id, std::string_view name) {
  return intern(SymbolKind::State, {id.index, 0, 0}, name);
}

uint32_t IndexBuilder::outcome(ir::StateId state, std::string_view name) {
  return intern(SymbolKind::Outcome, {state.index, 0, 0}, name);
}

uint32_t IndexBuilder::key(ir::StateId scope, std::string_view name) {
  return intern(SymbolKind::UserdataKey, {scope.index, 0, 0}, name);
}

uint32_t IndexBuilder::templateName(std::string_view name) {
  return intern(SymbolKind::Template, {0, 0, 0}, name);
}

uint32_t IndexBuilder::subScript(uint32_t file, std::string_view name) {
  return intern(SymbolKind::SubScript, {file, 0, 0}, name, file);
}

uint32_t IndexBuilder::param(const SourceLoc& definition, std::string_view name) {
  return intern(SymbolKind::Param, {definition.file, definition.line, definition.column}, name);
}

uint32_t IndexBuilder::undefinedParam(ir::StateId state, std::string_view name) {
  return intern(SymbolKind::Param, {kNone, state.index, 0}, name);
}

uint32_t IndexBuilder::intern(SymbolKind kind, std::tuple<uint32_t, uint32_t, uint32_t> at,
                              std::string_view name, uint32_t file) {
  auto key = std::tuple_cat(std::tuple(kind), at, std::tuple(std::string(name)));
  auto [it, inserted] = interned_.try_emplace(std::move(key), symbols_.size());
  if (inserted) {
    symbols_.push_back({kind, std::string(name), file});
    parent_.push_back(it->second);
  }
  return it->second;
}

void IndexBuilder::add(const SourceLoc& loc, uint32_t symbol, Role role, Site site,
                       ir::StateId holder, ir::StateId scope) {
  if (!loc.hasFile() || !loc.hasLine()) return;
  auto [it, inserted] =
      recorded_.try_emplace({loc.file, loc.line, loc.column}, occurrences_.size());
  if (inserted) {
    occurrences_.push_back({loc, symbol, role, site, holder, scope});
    return;
  }
  Occurrence& earlier = occurrences_[it->second];
  if (symbols_[earlier.symbol].kind != symbols_[symbol].kind) return;
  join(earlier.symbol, symbol);
  if (role == Role::Definition) earlier.role = Role::Definition;
}

void IndexBuilder::feed(uint32_t symbol, uint32_t source) { feeds_.emplace_back(symbol, source); }

uint32_t IndexBuilder::root(uint32_t symbol) {
  while (parent_[symbol] != symbol) {
    parent_[symbol] = parent_[parent_[symbol]];
    symbol = parent_[symbol];
  }
  return symbol;
}

void IndexBuilder::join(uint32_t a, uint32_t b) {
  a = root(a);
  b = root(b);
  if (a != b) parent_[std::max(a, b)] = std::min(a, b);
}

IndexContents IndexBuilder::finish() {
  IndexContents contents;
  contents.fed_by.resize(symbols_.size());
  for (auto [symbol, source] : feeds_) {
    uint32_t to = root(symbol);
    uint32_t from = root(source);
    if (to != from) contents.fed_by[to].push_back(from);
  }
  for (Occurrence& occurrence : occurrences_) occurrence.symbol = root(occurrence.symbol);
  contents.symbols = std::move(symbols_);
  contents.occurrences = std::move(occurrences_);
  return contents;
}

}  // namespace smachac::lsp
