// The cursor's context: the sketch reader stopped at the cursor, and what it left open.
#include "lsp/yaml_context.h"

#include <algorithm>
#include <cctype>

#include "lsp/yaml_sketch.h"

namespace smachac::lsp {
namespace {

/// The segment a collection still open at the cursor adds to the path: the key of its last
/// entry, or the index of its item. `in_last_entry`: the item the cursor is in exists already
/// (else the cursor starts the next one).
void addSegment(const SketchFrame& frame, bool in_last_entry, std::vector<PathSegment>& path) {
  if (frame.isMap()) {
    if (!frame.node.asMap().empty()) path.push_back({frame.node.asMap().back().key, -1});
    return;
  }
  auto size = static_cast<int64_t>(frame.node.asList().size());
  path.push_back({"", frame.awaiting || in_last_entry ? std::max<int64_t>(size - 1, 0) : size});
}

/// `through_top`: the innermost collection's last entry holds the cursor (Value, Item).
std::vector<PathSegment> pathOf(const std::vector<SketchFrame>& frames, bool through_top,
                                bool in_token) {
  std::vector<PathSegment> path;
  for (size_t i = 0; i < frames.size(); ++i) {
    bool top = i + 1 == frames.size();
    if (!top) {
      addSegment(frames[i], true, path);
    } else if (through_top) {
      addSegment(frames[i], in_token, path);
    }
  }
  return path;
}

CursorRole roleOf(SketchExpect expect) {
  switch (expect) {
    case SketchExpect::Key:
      return CursorRole::Key;
    case SketchExpect::Value:
      return CursorRole::Value;
    case SketchExpect::Item:
      return CursorRole::Item;
    case SketchExpect::Nothing:
    case SketchExpect::LineStart:
      return CursorRole::None;
  }
  return CursorRole::None;
}

/// A cursor in the indentation of a line: a key of the mapping at its column, or of a new
/// mapping under a key that has no value yet.
void placeAtLineStart(const SketchReader& reader, YamlContext& context) {
  const std::vector<SketchFrame>& frames = reader.openFrames();
  if (frames.empty()) {
    if (!reader.hasRoot()) context.role = CursorRole::Key;
    return;
  }
  const SketchFrame& top = frames.back();
  if (!top.isMap()) return;
  if (top.column == reader.lineStartColumn()) {
    context.role = CursorRole::Key;
    context.path = pathOf(frames, false, false);
  } else if (top.awaiting) {
    context.role = CursorRole::Key;
    context.path = pathOf(frames, true, false);
  }
}

/// The word around the cursor: back to the start of the scalar the cursor is in (after its
/// quote), forward over word bytes.
void findWord(std::string_view text, size_t offset, size_t content_begin, YamlContext& context) {
  size_t begin = offset;
  while (begin > content_begin && isWordByte(text[begin - 1])) --begin;
  size_t end = offset;
  while (end < text.size() && isWordByte(text[end])) ++end;
  context.word_begin = begin;
  context.word_end = end;
  context.prefix = std::string(text.substr(begin, offset - begin));
}

}  // namespace

bool isWordByte(char c) {
  auto byte = static_cast<unsigned char>(c);
  return std::isalnum(byte) || c == '_' || c == '-' || c == '.' || c == '/' || byte >= 0x80;
}

YamlContext yamlContextAt(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  SketchReader reader(text.substr(0, offset), 0);
  reader.read();
  YamlContext context;
  context.in_comment = reader.endsInComment();
  const std::optional<SketchToken>& token = reader.lastToken();
  bool in_token = token && token->end == offset && (!token->quote || !token->closed);
  size_t content_begin = in_token ? token->begin + (token->quote ? 1 : 0) : offset;
  findWord(text, offset, content_begin, context);
  if (context.in_comment) return context;
  context.quoted = in_token && token->quote;
  context.in_code = in_token && content_begin < offset && text[content_begin] == '`';
  const std::vector<SketchFrame>& frames = reader.openFrames();
  context.in_flow = !frames.empty() && frames.back().isFlow();
  if (!in_token && reader.expect() == SketchExpect::LineStart) {
    placeAtLineStart(reader, context);
    return context;
  }
  context.role = roleOf(in_token ? token->role : reader.expect());
  bool through_top = context.role == CursorRole::Value || context.role == CursorRole::Item;
  context.path = pathOf(frames, through_top, in_token);
  return context;
}

std::string describePath(const std::vector<PathSegment>& path) {
  std::string text;
  for (const PathSegment& segment : path) {
    if (!text.empty()) text += '/';
    text += segment.isItem() ? "[" + std::to_string(segment.index) + "]" : segment.key;
  }
  return text;
}

}  // namespace smachac::lsp
