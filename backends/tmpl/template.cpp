// Template compilation: normalise, tokenise, parse, analyse scopes.
#include "backends/tmpl/template.h"

#include <algorithm>

#include "backends/tmpl/ast/scope.h"
#include "backends/tmpl/lexer/lexer.h"
#include "backends/tmpl/lexer/token_table.h"
#include "backends/tmpl/parser/parser.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {

Template::Template(std::string name, std::string origin, std::string_view source,
                   const Registry& registry, bool builtin, std::span<const uint32_t> tokens,
                   std::span<const uint8_t> image)
    : name_(std::move(name)), origin_(std::move(origin)), registry_(registry) {
  std::optional<std::string_view> in_place =
      builtin ? normalizedInPlace(source) : std::optional<std::string_view>();
  if (in_place) {
    source_ = *in_place;
  } else {
    owned_source_ = normalizeSource(source);
    source_ = owned_source_;
  }
  if (builtin && !image.empty() && loadImage(image)) return;
  try {
    std::optional<std::span<const Token>> stored = storedTokens(tokens, source_);
    std::vector<Token> lexed = stored ? std::vector<Token>() : tokenize(source_);
    std::span<const Token> stream = stored ? *stored : std::span<const Token>(lexed);
    ParsedTemplate parsed = parseTemplate(source_, stream, registry, arena_, builtin);
    analyzeScopes(parsed, root_frame_);
    adopt(parsed);
    deferred_ = std::move(parsed.deferred);
    if (!deferred_.empty()) keepTokens(stream, std::move(lexed));
  } catch (const SyntaxFault& fault) {
    throw error(fault.pos, fault.message);
  }
}

template <typename Compiled>
void Template::adopt(Compiled& compiled) {
  body_ = std::move(compiled.body);
  blocks_ = std::move(compiled.blocks);
  references_ = std::move(compiled.references);
  has_extends_ = compiled.has_extends;
  names_templates_ = compiled.names_templates;
}

bool Template::loadImage(std::span<const uint8_t> image) {
  std::unique_ptr<ImageReader> reader = ImageReader::open(image, source_, registry_);
  ImageTemplate loaded;
  if (!reader || !reader->readTemplate(arena_, loaded)) return false;
  adopt(loaded);
  root_frame_ = std::move(loaded.root_frame);
  image_deferred_ = std::move(loaded.deferred);
  if (!image_deferred_.empty()) image_reader_ = std::move(reader);
  from_image_ = true;
  return true;
}

void Template::completeFromImage(const MacroStmt& macro) const {
  auto it = std::find_if(image_deferred_.begin(), image_deferred_.end(),
                         [&](const ImageMacro& d) { return d.macro == &macro; });
  if (it == image_deferred_.end()) return;
  try {
    image_reader_->readMacro(*it, arena_);
  } catch (const Fault& fault) {
    throw error(macro.pos, fault.message());
  }
  it->macro->deferred = false;
  image_deferred_.erase(it);
  if (image_deferred_.empty()) image_reader_.reset();
}

void Template::completeMacro(const MacroStmt& macro) const {
  if (from_image_) return completeFromImage(macro);
  auto it = std::find_if(deferred_.begin(), deferred_.end(),
                         [&](const DeferredMacro& d) { return d.macro == &macro; });
  if (it == deferred_.end()) return;
  try {
    Parser parser(source_, tokens_, registry_, arena_);
    parser.parseDeferredMacro(*it);
    analyzeDeferredMacro(*it);
  } catch (const SyntaxFault& fault) {
    throw error(fault.pos, fault.message);
  }
  it->macro->deferred = false;
  deferred_.erase(it);
  if (deferred_.empty()) keepTokens({}, {});
}

void Template::keepTokens(std::span<const Token> stream, std::vector<Token> lexed) const {
  lexed_tokens_ = std::move(lexed);
  tokens_ = lexed_tokens_.empty() ? stream : std::span<const Token>(lexed_tokens_);
}

const BlockStmt* Template::block(std::string_view name) const {
  for (const BlockStmt* b : blocks_) {
    if (*b->name == name) return b;
  }
  return nullptr;
}

std::pair<int, int> Template::lineColumn(uint32_t pos) const {
  if (pos > source_.size()) pos = static_cast<uint32_t>(source_.size());
  int line = 1;
  size_t line_start = 0;
  for (size_t i = 0; i < pos; ++i) {
    if (source_[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  int column = 1 + static_cast<int>(unicode::length(source_.substr(line_start, pos - line_start)));
  return {line, column};
}

TemplateError Template::error(uint32_t pos, std::string message) const {
  auto [line, column] = lineColumn(pos);
  return TemplateError(origin_, line, column, std::move(message));
}

}  // namespace smachac::tmpl
