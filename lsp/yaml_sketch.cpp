// The tolerant YAML reader: lines in block style, characters in flow style.
#include "lsp/yaml_sketch.h"

#include <algorithm>

namespace smachac::lsp {
namespace {

using Kind = SketchFrame::Kind;

/// Deeper collections are read as part of the one at this depth: no script nests this deep,
/// and the tree's recursive walks (and destructor) stay shallow.
constexpr size_t kMaxDepth = 200;

bool isSpace(char c) { return c == ' ' || c == '\t'; }

bool isFlowIndicator(char c) { return c == ',' || c == '[' || c == ']' || c == '{' || c == '}'; }

size_t skipSpaces(std::string_view text, size_t pos, size_t end) {
  while (pos < end && isSpace(text[pos])) ++pos;
  return pos;
}

/// After an anchor or a tag (`&a`, `!expr`): the next space or flow indicator.
size_t skipProperty(std::string_view text, size_t pos, size_t end) {
  while (pos < end && !isSpace(text[pos]) && !isFlowIndicator(text[pos])) ++pos;
  return pos;
}

bool isDash(std::string_view text, size_t pos, size_t end) {
  return text[pos] == '-' && (pos + 1 == end || isSpace(text[pos + 1]));
}

bool isDocumentMarker(std::string_view line) {
  bool marker = line.starts_with("---") || line.starts_with("...");
  return marker && (line.size() == 3 || isSpace(line[3]));
}

/// Just after the closing quote of the scalar that opens at `pos`, or npos.
size_t closingQuote(std::string_view text, size_t pos, size_t end) {
  char quote = text[pos];
  for (size_t i = pos + 1; i < end; ++i) {
    if (quote == '"' && text[i] == '\\') {
      ++i;
    } else if (text[i] == quote && quote == '\'' && i + 1 < end && text[i + 1] == '\'') {
      ++i;
    } else if (text[i] == quote) {
      return i + 1;
    }
  }
  return std::string_view::npos;
}

/// Where a plain scalar that starts at `pos` ends, trailing spaces excluded.
size_t plainEnd(std::string_view text, size_t pos, size_t end, bool flow) {
  size_t i = pos;
  for (; i < end; ++i) {
    char c = text[i];
    if (c == '#' && i > pos && isSpace(text[i - 1])) break;
    bool indicator_follows =
        i + 1 == end || isSpace(text[i + 1]) || (flow && isFlowIndicator(text[i + 1]));
    if (c == ':' && indicator_follows) break;
    if (flow && isFlowIndicator(c)) break;
  }
  while (i > pos && isSpace(text[i - 1])) --i;
  return i;
}

/// The character a double-quoted scalar's `\c` stands for (the common escapes).
char unescaped(char c) {
  switch (c) {
    case 'n':
      return '\n';
    case 't':
      return '\t';
    case '0':
      return '\0';
    default:
      return c;
  }
}

}  // namespace

void SketchReader::read() {
  size_t begin = 0;
  while (true) {
    size_t newline = text_.find('\n', begin);
    size_t end = newline == std::string_view::npos ? text_.size() : newline;
    size_t content_end = end > begin && text_[end - 1] == '\r' ? end - 1 : end;
    readLine(begin, content_end, newline == std::string_view::npos);
    if (newline == std::string_view::npos) return;
    begin = newline + 1;
  }
}

void SketchReader::readLine(size_t begin, size_t end, bool last) {
  ++line_;
  line_begin_ = begin;
  ends_in_comment_ = false;
  size_t pos = skipSpaces(text_, begin, end);
  line_indent_ = columnOf(pos);
  bool blank = pos == end || text_[pos] == '#';
  if (flowOpen() && (!blank || last) && line_indent_ <= flow_line_indent_) closeFlows();
  if (flowOpen()) return endOfLine(readFlow(pos, end), end);
  if (block_scalar_indent_ >= 0 && ((blank && !last) || line_indent_ > block_scalar_indent_)) {
    expect_ = SketchExpect::Nothing;
    return;
  }
  block_scalar_indent_ = -1;
  if (pos == end) {
    if (!last) return;
    closeBlocks(line_indent_, false);
    expect_ = SketchExpect::LineStart;
    line_start_column_ = line_indent_;
    return;
  }
  if (text_[pos] == '#') return endOfLine(pos, end);
  if (pos == begin && isDocumentMarker(text_.substr(pos, end - pos))) {
    expect_ = SketchExpect::Nothing;
    return;
  }
  closeBlocks(line_indent_, isDash(text_, pos, end));
  readBlockContent(pos, end);
}

void SketchReader::endOfLine(size_t pos, size_t end) {
  pos = skipSpaces(text_, pos, end);
  if (pos < end && text_[pos] == '#') {
    ends_in_comment_ = end == text_.size();
    expect_ = SketchExpect::Nothing;
  }
}

void SketchReader::readBlockContent(size_t pos, size_t end) {
  SketchExpect slot = SketchExpect::Nothing;  // Value or Item once this line opened one
  while (pos < end) {
    char c = text_[pos];
    if (isDash(text_, pos, end)) {
      pos = readDash(pos, end);
      slot = SketchExpect::Item;
    } else if (c == '#') {
      return endOfLine(pos, end);
    } else if (c == '{' || c == '[') {
      flow_line_indent_ = line_indent_;
      return endOfLine(readFlow(pos, end), end);
    } else if (c == '&' || c == '!') {
      property_begin_ = pos;
      pos = skipSpaces(text_, skipProperty(text_, pos, end), end);
    } else if ((c == '|' || c == '>') && slot != SketchExpect::Nothing) {
      return startBlockScalar(pos);
    } else {
      SketchToken token = scanScalar(pos, end, false);
      size_t after = skipSpaces(text_, token.end, end);
      if (!isKeyColon(after, end)) {
        placeScalar(token, slot);
        return endOfLine(token.end, end);
      }
      readKey(token);
      pos = skipSpaces(text_, after + 1, end);
      slot = SketchExpect::Value;
    }
  }
}

size_t SketchReader::readDash(size_t pos, size_t end) {
  bool continues = !frames_.empty() && frames_.back().kind == Kind::BlockSeq &&
                   frames_.back().column == columnOf(pos);
  if (!continues) open(Kind::BlockSeq, pos);
  addItem(pos);
  expect_ = SketchExpect::Item;
  return skipSpaces(text_, pos + 1, end);
}

void SketchReader::readKey(SketchToken token) {
  blockMapAt(columnOf(token.begin), token.begin);
  token.role = SketchExpect::Key;
  addKey(token);
  last_token_ = token;
  expect_ = SketchExpect::Value;
}

void SketchReader::placeScalar(SketchToken token, SketchExpect slot) {
  expect_ = SketchExpect::Nothing;
  if (slot != SketchExpect::Nothing) {
    token.role = slot;
    attach(scalarValue(token));
  } else if (!frames_.empty() && frames_.back().column < columnOf(token.begin)) {
    // Deeper than the innermost collection: the value of its last key or item, or the
    // continuation of a scalar (ignored); under a key, a key being typed.
    SketchFrame& top = frames_.back();
    if (!top.awaiting) return;
    if (top.isMap()) return readKeyAlone(token);
    token.role = SketchExpect::Item;
    attach(scalarValue(token));
  } else {
    return readKeyAlone(token);
  }
  last_token_ = token;
}

void SketchReader::readKeyAlone(SketchToken token) {
  blockMapAt(columnOf(token.begin), token.begin);
  token.role = SketchExpect::Key;
  addKey(token);
  if (!frames_.empty()) frames_.back().awaiting = false;
  last_token_ = token;
  expect_ = SketchExpect::Nothing;
}

void SketchReader::startBlockScalar(size_t pos) {
  attach(ir::Value::string("", locAt(pos, 1)));
  // Its lines are those deeper than the collection that holds it.
  block_scalar_indent_ = frames_.empty() ? line_indent_ : frames_.back().column;
  expect_ = SketchExpect::Nothing;
}

bool SketchReader::isKeyColon(size_t pos, size_t end) const {
  return pos < end && text_[pos] == ':' && (pos + 1 == end || isSpace(text_[pos + 1]));
}

size_t SketchReader::readFlow(size_t pos, size_t end) {
  while (pos < end) {
    char c = text_[pos];
    bool opener = c == '{' || c == '[';
    if (!flowOpen() && !opener) return pos;
    if (isSpace(c)) {
      ++pos;
    } else if (c == '#' && (pos == line_begin_ || isSpace(text_[pos - 1]))) {
      return pos;
    } else if (opener) {
      open(c == '{' ? Kind::FlowMap : Kind::FlowSeq, pos++);
      expect_ = c == '{' ? SketchExpect::Key : SketchExpect::Item;
    } else if (c == '}' || c == ']') {
      while (frames_.back().implicit) close();
      close();
      expect_ = SketchExpect::Nothing;
      if (!flowOpen()) return pos + 1;
      ++pos;
    } else if (c == ',') {
      while (frames_.back().implicit) close();
      frames_.back().awaiting = false;
      expect_ = frames_.back().isMap() ? SketchExpect::Key : SketchExpect::Item;
      ++pos;
    } else if (c == ':') {
      ++pos;
    } else if (c == '&' || c == '!') {
      property_begin_ = pos;
      pos = skipProperty(text_, pos, end);
    } else {
      pos = readFlowScalar(pos, end);
    }
  }
  return end;
}

size_t SketchReader::readFlowScalar(size_t pos, size_t end) {
  SketchToken token = scanScalar(pos, end, true);
  if (token.end == token.begin) return pos + 1;
  size_t after = skipSpaces(text_, token.end, end);
  bool colon = after < end && text_[after] == ':';
  if (colon && !frames_.back().isMap()) {
    size_t depth = frames_.size();
    open(Kind::FlowMap, token.begin);
    if (frames_.size() > depth) frames_.back().implicit = true;
  }
  SketchFrame& top = frames_.back();
  expect_ = SketchExpect::Nothing;
  if (top.isMap() && !top.awaiting) {
    token.role = SketchExpect::Key;
    addKey(token);
    frames_.back().awaiting = colon;
    if (colon) expect_ = SketchExpect::Value;
  } else {
    token.role = top.isMap() ? SketchExpect::Value : SketchExpect::Item;
    attach(scalarValue(token));
  }
  last_token_ = token;
  return colon ? after + 1 : token.end;
}

SketchToken SketchReader::scanScalar(size_t pos, size_t end, bool flow) const {
  SketchToken token;
  token.begin = pos;
  char c = text_[pos];
  if (c != '\'' && c != '"') {
    token.end = plainEnd(text_, pos, end, flow);
    return token;
  }
  token.quote = c;
  token.end = closingQuote(text_, pos, end);
  token.closed = token.end != std::string_view::npos;
  if (!token.closed) token.end = end;
  return token;
}

std::string SketchReader::scalarText(const SketchToken& token) const {
  std::string_view raw = text_.substr(token.begin, token.end - token.begin);
  if (!token.quote) return std::string(raw);
  raw.remove_prefix(1);
  if (token.closed) raw.remove_suffix(1);
  std::string text;
  for (size_t i = 0; i < raw.size(); ++i) {
    bool escape = token.quote == '"' ? raw[i] == '\\' : raw[i] == '\'';
    if (!escape || i + 1 == raw.size()) {
      text += raw[i];
    } else if (token.quote == '\'') {
      text += raw[++i];
    } else {
      text += unescaped(raw[++i]);
    }
  }
  return text;
}

ir::Value SketchReader::scalarValue(const SketchToken& token) {
  // A tagged scalar is located at its tag, as the frontend locates it.
  size_t begin = std::min(property_begin_, token.begin);
  property_begin_ = std::string_view::npos;
  return ir::Value::string(scalarText(token), locAt(begin, token.end - begin));
}

void SketchReader::open(Kind kind, size_t pos) {
  property_begin_ = std::string_view::npos;
  if (frames_.size() >= kMaxDepth) return;
  if (!frames_.empty() && !frames_.back().isMap() && !frames_.back().awaiting) addItem(pos);
  SketchFrame frame;
  frame.kind = kind;
  frame.column = columnOf(pos);
  bool map = kind == Kind::BlockMap || kind == Kind::FlowMap;
  frame.node = map ? ir::Value::map({}, locAt(pos, 1)) : ir::Value::list({}, locAt(pos, 1));
  frames_.push_back(std::move(frame));
}

void SketchReader::close() {
  ir::Value node = std::move(frames_.back().node);
  frames_.pop_back();
  attach(std::move(node));
}

void SketchReader::closeBlocks(uint32_t indent, bool dash) {
  while (!frames_.empty() && !frames_.back().isFlow()) {
    const SketchFrame& top = frames_.back();
    bool deeper = top.column > indent;
    bool sequence_ends = top.kind == Kind::BlockSeq && top.column == indent && !dash;
    if (!deeper && !sequence_ends) return;
    close();
  }
}

void SketchReader::closeFlows() {
  while (flowOpen()) close();
}

void SketchReader::attach(ir::Value value) {
  if (frames_.empty()) {
    if (!root_) root_ = std::move(value);
    return;
  }
  SketchFrame& top = frames_.back();
  if (top.isMap()) {
    if (top.awaiting) top.node.asMap().back().value = std::move(value);
  } else if (top.awaiting) {
    top.node.asList().back() = std::move(value);
  } else {
    top.node.asList().push_back(std::move(value));
  }
  top.awaiting = false;
}

void SketchReader::addKey(const SketchToken& token) {
  property_begin_ = std::string_view::npos;
  if (frames_.empty() || !frames_.back().isMap()) return;  // only past kMaxDepth
  std::string text = scalarText(token);
  SourceLoc loc = locAt(token.begin, text.size());
  frames_.back().node.asMap().push_back({std::move(text), loc, ir::Value::null(loc)});
  frames_.back().awaiting = true;
}

void SketchReader::addItem(size_t pos) {
  if (frames_.empty() || frames_.back().isMap()) return;  // only past kMaxDepth
  frames_.back().node.asList().push_back(ir::Value::null(locAt(pos, 1)));
  frames_.back().awaiting = true;
}

void SketchReader::blockMapAt(uint32_t column, size_t pos) {
  bool open_here =
      !frames_.empty() && frames_.back().kind == Kind::BlockMap && frames_.back().column == column;
  if (!open_here) open(Kind::BlockMap, pos);
}

SourceLoc SketchReader::locAt(size_t pos, size_t length) const {
  return {file_, line_, columnOf(pos) + 1, static_cast<uint32_t>(std::max<size_t>(length, 1))};
}

ir::Value SketchReader::finish() {
  while (!frames_.empty()) close();
  return root_ ? std::move(*root_) : ir::Value::null(SourceLoc{file_, 1, 1, 1});
}

ir::Value sketchYaml(std::string_view text, uint32_t file) {
  SketchReader reader(text, file);
  reader.read();
  return reader.finish();
}

}  // namespace smachac::lsp
