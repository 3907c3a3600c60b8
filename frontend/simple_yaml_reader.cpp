// The block structure of the simple YAML reader. Every function returns false to give up.
//
// Invariant: a function that finishes a line leaves the cursor on the first non-space byte of
// the next line holding content (comment and blank lines skipped), with `indent_` its column,
// or at the end of the text with `indent_` -1.
#include "frontend/simple_yaml_reader.h"

#include <climits>

#include "frontend/simple_yaml_scan.h"
#include "frontend/yaml_value_builder.h"

namespace smachac::frontend {
namespace {

constexpr int kNoLimit = INT_MAX;
constexpr int kMaxDepth = 64;          ///< deeper documents are left to yaml-cpp
constexpr size_t kMaxKeyBytes = 1024;  ///< YAML's limit on implicit keys

class SimpleYamlReader {
 public:
  SimpleYamlReader(std::string_view text, YamlValueBuilder& builder) : builder_(builder) {
    cursor_.text = text;
  }

  bool read() {
    if (!hasOnlySimpleBytes(cursor_.text) || !skipToContent(kNoLimit)) return false;
    if (indent_ == 0 && atDocumentStart()) {
      cursor_.pos += 3;
      if (!lineEnd(kNoLimit)) return false;
    }
    if (indent_ != 0 || !blockNode(0)) return false;
    return indent_ < 0;
  }

 private:
  /// Counts the nesting of collections; the reader gives up past kMaxDepth.
  class DepthGuard {
   public:
    explicit DepthGuard(int& depth) : depth_(++depth) {}
    ~DepthGuard() { --depth_; }
    bool tooDeep() const { return depth_ > kMaxDepth; }

   private:
    int& depth_;
  };

  bool atDocumentStart() const {
    char after = cursor_.peek(3);
    return cursor_.text.substr(cursor_.pos).starts_with("---") &&
           (after == ' ' || after == '\n' || after == '\0');
  }

  bool atSequenceEntry() const {
    char after = cursor_.peek(1);
    return cursor_.peek() == '-' && (after == ' ' || after == '\n' || after == '\0');
  }

  bool atLineEndOrComment() const { return cursor_.atLineEnd() || cursor_.peek() == '#'; }

  /// From the start of a line to the next line with content. After a plain scalar, a line
  /// deeper than `limit` would continue it (even a comment line, for yaml-cpp): give up.
  bool skipToContent(int limit) {
    while (true) {
      cursor_.skipSpaces();
      if (cursor_.atEnd()) {
        indent_ = -1;
        return true;
      }
      if (cursor_.peek() != '\n') {
        if (cursor_.column() > limit) return false;
        if (cursor_.peek() != '#') {
          indent_ = cursor_.column();
          return true;
        }
      }
      cursor_.nextLine();
    }
  }

  /// The rest of a line (spaces and a comment) and the lines up to the next content.
  bool lineEnd(int limit) {
    cursor_.skipSpaces();
    if (cursor_.peek() == '#') {
      if (cursor_.pos == cursor_.line_start || cursor_.text[cursor_.pos - 1] != ' ') return false;
    } else if (!cursor_.atLineEnd()) {
      return false;
    }
    cursor_.nextLine();
    return skipToContent(limit);
  }

  void emit(const YamlScalar& s) {
    if (!s.quoted && isNullPlain(s.text)) {
      builder_.onNull(s.mark, 0);
    } else {
      builder_.onScalar(s.mark, s.quoted ? "!" : "?", 0, s.text);
    }
  }

  /// A mapping key (plain or quoted) and its `:`.
  bool scanKey(YamlCursor& c, YamlScalar& key) const {
    char ch = c.peek();
    if (ch == '"' || ch == '\'') {
      if (!scanQuoted(c, key)) return false;
    } else if (!startsSimplePlain(c) || !scanPlain(c, YamlContext::Block, key)) {
      return false;
    }
    char after = c.peek(1);
    if (c.peek() != ':' || (after != ' ' && after != '\n' && after != '\0')) return false;
    if (key.text.size() > kMaxKeyBytes) return false;
    ++c.pos;
    return true;
  }

  bool looksLikeKey() const {
    YamlCursor probe = cursor_;
    YamlScalar key;
    return scanKey(probe, key);
  }

  bool blockMap(int col) {
    DepthGuard depth(depth_);
    if (depth.tooDeep()) return false;
    builder_.onMapStart(cursor_.mark(), 0);
    while (true) {
      YamlScalar key;
      if (!scanKey(cursor_, key)) return false;
      emit(key);
      if (!mapValue(col, key.mark.line)) return false;
      if (indent_ < col) break;
      if (indent_ > col) return false;
    }
    builder_.onCollectionEnd();
    return true;
  }

  bool mapValue(int col, int key_line) {
    cursor_.skipSpaces();
    if (!atLineEndOrComment()) return inlineValue(col);
    if (!lineEnd(kNoLimit)) return false;
    if (indent_ > col) return blockNode(indent_);
    if (indent_ == col && atSequenceEntry()) return blockSequence(col, /*indentless=*/true);
    // No value: yaml-cpp marks the null with the next token, which the builder replaces by
    // the key's location when it is on another line.
    YamlMark next = cursor_.mark();
    if (next.line == key_line) return false;
    builder_.onNull(next, 0);
    return true;
  }

  bool blockNode(int col) {
    return atSequenceEntry() ? blockSequence(col, /*indentless=*/false) : blockMap(col);
  }

  bool blockSequence(int col, bool indentless) {
    DepthGuard depth(depth_);
    if (depth.tooDeep()) return false;
    builder_.onSequenceStart(cursor_.mark(), 0);
    while (true) {
      ++cursor_.pos;  // the `-`
      if (!sequenceItem(col)) return false;
      if (indent_ < col) break;
      if (indent_ > col) return false;
      if (!atSequenceEntry()) {
        if (indentless) break;
        return false;
      }
    }
    builder_.onCollectionEnd();
    return true;
  }

  bool sequenceItem(int col) {
    cursor_.skipSpaces();
    if (atLineEndOrComment()) {
      if (!lineEnd(kNoLimit)) return false;
      return indent_ > col && blockNode(indent_);  // an empty item is left to yaml-cpp
    }
    if (atSequenceEntry()) return false;
    if (looksLikeKey()) return blockMap(cursor_.column());
    return inlineValue(col);
  }

  /// `!expr` and a quoted scalar on its line (other tags and forms: yaml-cpp), reported at
  /// the tag as yaml-cpp reports it.
  bool portableExpr() {
    if (cursor_.text.substr(cursor_.pos, kPortableExprTag.size() + 1) != "!expr ") return false;
    YamlMark tag = cursor_.mark();
    cursor_.pos += kPortableExprTag.size();
    cursor_.skipSpaces();
    YamlScalar s;
    if ((cursor_.peek() != '"' && cursor_.peek() != '\'') || !scanQuoted(cursor_, s)) return false;
    builder_.onScalar(tag, kPortableExprTag, 0, s.text);
    return true;
  }

  /// A value on the line of its key or `-`; `limit` is the column of the collection it is in.
  bool inlineValue(int limit) {
    char ch = cursor_.peek();
    if (ch == '[' || ch == '{') {
      flow_limit_ = limit;
      return flowNode() && lineEnd(kNoLimit);
    }
    if (ch == '!') return portableExpr() && lineEnd(kNoLimit);
    YamlScalar s;
    if (ch == '"' || ch == '\'') {
      if (!scanQuoted(cursor_, s)) return false;
      emit(s);
      return lineEnd(kNoLimit);
    }
    if (!startsSimplePlain(cursor_) || !scanPlain(cursor_, YamlContext::Block, s)) return false;
    if (cursor_.peek() == ':') return false;  // `a: b: c`
    emit(s);
    return lineEnd(limit);
  }

  bool flowNode() {
    DepthGuard depth(depth_);
    if (depth.tooDeep()) return false;
    char ch = cursor_.peek();
    if (ch == '[') return flowSequence();
    if (ch == '{') return flowMap();
    if (ch == '!') return portableExpr();
    YamlScalar s;
    if (ch == '"' || ch == '\'') {
      if (!scanQuoted(cursor_, s)) return false;
    } else if (!startsSimplePlain(cursor_) || !scanPlain(cursor_, YamlContext::Flow, s)) {
      return false;
    }
    emit(s);
    return true;
  }

  /// The spaces after a flow collection's opening bracket or comma, and the line breaks: the
  /// collection goes on over lines deeper than the block collection it is in (blank lines
  /// between them; a comment, or a line break anywhere else, is left to yaml-cpp).
  bool skipFlowSpace() {
    cursor_.skipSpaces();
    if (cursor_.peek() != '\n') return true;
    while (cursor_.peek() == '\n') {
      cursor_.nextLine();
      cursor_.skipSpaces();
    }
    return cursor_.column() > flow_limit_;
  }

  /// After an entry: `,` and the next entry, or the closing bracket (true in `closed`).
  bool flowSeparator(char close, bool& closed) {
    cursor_.skipSpaces();
    char ch = cursor_.peek();
    ++cursor_.pos;
    closed = ch == close;
    if (closed) return true;
    if (ch != ',') return false;
    return skipFlowSpace() && cursor_.peek() != close;  // a trailing comma: yaml-cpp
  }

  bool flowSequence() {
    builder_.onSequenceStart(cursor_.mark(), 0);
    ++cursor_.pos;
    if (!skipFlowSpace()) return false;
    bool closed = cursor_.peek() == ']';
    if (closed) ++cursor_.pos;
    while (!closed) {
      if (!flowNode() || !flowSeparator(']', closed)) return false;
    }
    builder_.onCollectionEnd();
    return true;
  }

  bool flowMap() {
    builder_.onMapStart(cursor_.mark(), 0);
    ++cursor_.pos;
    if (!skipFlowSpace()) return false;
    bool closed = cursor_.peek() == '}';
    if (closed) ++cursor_.pos;
    while (!closed) {
      if (!flowEntry() || !flowSeparator('}', closed)) return false;
    }
    builder_.onCollectionEnd();
    return true;
  }

  /// `key: value` in a flow mapping; an empty value is null, marked where it ends.
  bool flowEntry() {
    YamlScalar key;
    char ch = cursor_.peek();
    if (ch == '"' || ch == '\'') {
      if (!scanQuoted(cursor_, key)) return false;
    } else if (!startsSimplePlain(cursor_) || !scanPlain(cursor_, YamlContext::Flow, key)) {
      return false;
    }
    if (cursor_.peek() != ':' || cursor_.peek(1) != ' ') return false;
    emit(key);
    ++cursor_.pos;
    cursor_.skipSpaces();
    ch = cursor_.peek();
    if (ch != ',' && ch != '}') return flowNode();
    builder_.onNull(cursor_.mark(), 0);
    return true;
  }

  YamlCursor cursor_;
  YamlValueBuilder& builder_;
  int indent_ = -1;
  int depth_ = 0;
  int flow_limit_ = 0;  ///< the column of the block collection a flow collection is in
};

}  // namespace

std::optional<ir::Value> readSimpleYaml(uint32_t file, std::string_view text, StatesSink* sink) {
  DiagnosticEmitter unused;  // the builder gives up instead of reporting
  YamlValueBuilder builder(file, unused, YamlProblems::GiveUp, text);
  builder.setStatesSink(sink);
  if (!SimpleYamlReader(text, builder).read() || builder.gaveUp()) return std::nullopt;
  return builder.take();
}

}  // namespace smachac::frontend
