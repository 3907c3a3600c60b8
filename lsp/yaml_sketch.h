// A tolerant reading of YAML text, for an editor's documents, which are half-typed most of the
// time: it never fails, and it can stop anywhere (at the cursor) and say what is still open
// there. It reads the subset SMACHA scripts are written in, block and flow style:
//   * indentation makes the structure: a line closes the block collections indented deeper
//     than it, and a block sequence at its own column unless the line starts with `- `;
//   * `key:` (a colon before a space or the line's end) starts a mapping entry; a scalar alone
//     where a key could be is a key without a value (a key being typed);
//   * a flow collection may span lines, but a line indented no deeper than the line that
//     opened it closes it (its closing bracket is not typed yet);
//   * comments are skipped; so are block scalars (`|`, `>`), anchors, tags and `---`;
//     scalars stay strings; quoted scalars end at the line's end when their quote does not.
// Every value and key gets a SourceLoc as the frontend's YAML tree has them (1-based line and
// byte column; a collection's location is its first key or dash, or its bracket).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/value.h"

namespace smachac::lsp {

/// A collection the reader has not closed yet.
struct SketchFrame {
  enum class Kind : uint8_t { BlockMap, BlockSeq, FlowMap, FlowSeq };
  Kind kind = Kind::BlockMap;
  uint32_t column = 0;  ///< 0-based byte column of its keys or dashes, or of its bracket
  ir::Value node;       ///< the mapping or list read so far
  /// The last key (or item) has no value yet: what comes next is its value.
  bool awaiting = false;
  /// A mapping of one pair written `key: value` as an item of a flow sequence: it ends at the
  /// sequence's next `,` or at its bracket.
  bool implicit = false;

  bool isMap() const { return kind == Kind::BlockMap || kind == Kind::FlowMap; }
  bool isFlow() const { return kind == Kind::FlowMap || kind == Kind::FlowSeq; }
};

/// What the text may continue with where it ends.
enum class SketchExpect : uint8_t {
  Nothing,    ///< nothing that completes a key or a value (after a whole scalar or a bracket)
  Key,        ///< a key of the innermost mapping
  Value,      ///< the value of the innermost mapping's last key
  Item,       ///< an item of the innermost sequence
  LineStart,  ///< the text ends in the indentation of a line (see `lineStartColumn`)
};

/// A scalar as written: its bytes in the text and how it is quoted.
struct SketchToken {
  size_t begin = 0;
  size_t end = 0;
  char quote = 0;                             ///< '\'' or '"' for a quoted scalar
  bool closed = true;                         ///< false when its closing quote is missing
  SketchExpect role = SketchExpect::Nothing;  ///< Key, Value or Item: what the scalar is
};

class SketchReader {
 public:
  SketchReader(std::string_view text, uint32_t file) : text_(text), file_(file) {}

  /// Reads the whole text.
  void read();

  /// Where the text ends: the collections still open, outermost first.
  const std::vector<SketchFrame>& openFrames() const { return frames_; }
  SketchExpect expect() const { return expect_; }
  /// The last scalar read; it is what the text ends in when its `end` is the text's size.
  const std::optional<SketchToken>& lastToken() const { return last_token_; }
  bool endsInComment() const { return ends_in_comment_; }
  /// The indentation of the last line when the text ends in it (SketchExpect::LineStart).
  uint32_t lineStartColumn() const { return line_start_column_; }
  bool hasRoot() const { return root_.has_value(); }

  /// Closes what is open; the document (null for a text without any node).
  ir::Value finish();

 private:
  void readLine(size_t begin, size_t end, bool last);
  void readBlockContent(size_t pos, size_t end);
  size_t readDash(size_t pos, size_t end);
  void readKey(SketchToken token);
  void placeScalar(SketchToken token, SketchExpect slot);
  void readKeyAlone(SketchToken token);
  void startBlockScalar(size_t pos);
  size_t readFlow(size_t pos, size_t end);
  size_t readFlowScalar(size_t pos, size_t end);
  void endOfLine(size_t pos, size_t end);
  bool isKeyColon(size_t pos, size_t end) const;

  SketchToken scanScalar(size_t pos, size_t end, bool flow) const;
  std::string scalarText(const SketchToken& token) const;
  ir::Value scalarValue(const SketchToken& token);

  void open(SketchFrame::Kind kind, size_t pos);
  void close();
  void closeBlocks(uint32_t indent, bool dash);
  void closeFlows();
  void attach(ir::Value value);
  void addKey(const SketchToken& token);
  void addItem(size_t pos);
  /// The block mapping whose keys are at `column`, opened if needed.
  void blockMapAt(uint32_t column, size_t pos);
  bool flowOpen() const { return !frames_.empty() && frames_.back().isFlow(); }

  SourceLoc locAt(size_t pos, size_t length) const;
  uint32_t columnOf(size_t pos) const { return static_cast<uint32_t>(pos - line_begin_); }

  std::string_view text_;
  uint32_t file_;
  std::vector<SketchFrame> frames_;
  std::optional<ir::Value> root_;
  uint32_t line_ = 0;  ///< 1-based number of the line being read
  size_t line_begin_ = 0;
  uint32_t line_indent_ = 0;
  uint32_t flow_line_indent_ = 0;  ///< indentation of the line that opened the outer flow
  /// >= 0: the lines deeper than this column belong to a block scalar, and are skipped.
  int64_t block_scalar_indent_ = -1;
  SketchExpect expect_ = SketchExpect::LineStart;
  std::optional<SketchToken> last_token_;
  size_t property_begin_ = std::string_view::npos;  ///< the tag or anchor before a node
  bool ends_in_comment_ = false;
  uint32_t line_start_column_ = 0;
};

/// The document tree of `text`, read tolerantly (locations in file `file`).
ir::Value sketchYaml(std::string_view text, uint32_t file);

}  // namespace smachac::lsp
