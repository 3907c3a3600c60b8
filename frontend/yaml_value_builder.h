// Builds an ir::Value tree from YAML parse events (yaml-cpp's, or the simple reader's in
// simple_yaml_reader.h): keeps a location on every value and key, and reports as located
// diagnostics: non-scalar and duplicate keys, integer overflow, aliases of unfinished anchors,
// nesting deeper than kMaxYamlDepth and documents that expand (through aliases) to more than
// kMaxYamlNodes values or whose aliases copy more than kMaxYamlAliasBytes of text. Both
// readers feed the same builder, so they agree on everything but the events themselves.
// A StatesSink may take the items of the root's `states` list as they complete (streamed
// lowering, streamed_lowering.h); they are then missing from the tree.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "frontend/expr_scalar.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/value.h"

namespace smachac::frontend {

inline constexpr size_t kMaxYamlDepth = 1000;  ///< yaml-cpp itself stops at 2000
inline constexpr size_t kMaxYamlNodes = 4'000'000;
/// Text (scalars and keys) that aliases may copy in all: a script's own size limit.
inline constexpr size_t kMaxYamlAliasBytes = 32u << 20;

/// A 0-based position as yaml-cpp reports it; line -1 is yaml-cpp's "null mark".
struct YamlMark {
  int line = -1;
  int column = -1;
};

/// Where the root mapping's `states` list stands when one of its items is complete.
struct StatesListSite {
  SourceLoc root_loc;
  const ir::Map& root_entries;  ///< the root's entries read so far, `states` not among them
  SourceLoc states_key_loc;
  SourceLoc list_loc;
};

/// Takes the items of the root mapping's `states` list one by one, as soon as each is complete
/// (streamed_lowering.cpp lowers a big script's states while the rest is still being read).
class StatesSink {
 public:
  virtual ~StatesSink() = default;
  /// True when the sink took `item`; false leaves it in the list.
  virtual bool take(ir::Value& item, const StatesListSite& site) = 0;
};

/// What the builder does about a problem in the document.
enum class YamlProblems {
  Report,  ///< emit a diagnostic (and go on where the old path went on)
  GiveUp,  ///< emit nothing and stop: the caller parses the text again with yaml-cpp
};

class YamlValueBuilder {
 public:
  /// `document` is the text the events come from (it locates `!expr` scalars).
  YamlValueBuilder(uint32_t file, DiagnosticEmitter& diags, YamlProblems policy,
                   std::string_view document = {})
      : file_(file), diags_(diags), policy_(policy), exprs_(file, document) {}

  /// The document, or nullopt after an error that leaves no usable document.
  std::optional<ir::Value> take();
  bool aborted() const { return aborted_; }
  /// Hands the items of the root's `states` list to `sink` (nullptr: none) instead of the tree.
  void setStatesSink(StatesSink* sink) { sink_ = sink; }
  /// True when a problem was found under YamlProblems::GiveUp.
  bool gaveUp() const { return gave_up_; }

  /// `tag` is yaml-cpp's: "?" for plain scalars, "!" for quoted ones, else the node's tag.
  void onScalar(YamlMark mark, std::string_view tag, uint64_t anchor, std::string_view value);
  void onNull(YamlMark mark, uint64_t anchor);
  void onAlias(YamlMark mark, uint64_t anchor);
  void onSequenceStart(YamlMark mark, uint64_t anchor);
  void onMapStart(YamlMark mark, uint64_t anchor);
  void onCollectionEnd();

 private:
  /// A collection being built, and for maps the key waiting for its value. Frames are
  /// reused (with their buffers' capacity), so each collection gets one exact-size vector.
  struct Frame {
    bool is_map = false;
    SourceLoc loc;
    uint64_t anchor = 0;
    bool has_key = false;
    bool key_valid = false;
    std::string key;
    SourceLoc key_loc;
    ir::List items;
    ir::Map entries;
  };
  struct Anchored {
    ir::Value value;
    size_t nodes = 0;
    size_t bytes = 0;  ///< text of its scalars and keys
  };

  SourceLoc loc(YamlMark mark, size_t length = 1) const;
  ir::Value portableExpr(YamlMark mark, std::string_view value);
  template <DiagKind Kind, typename... Args>
  void report(SourceLoc where, const Args&... args);
  template <DiagNoteKind Note>
  void note(SourceLoc where);
  template <DiagKind Kind, typename Argument>
  void fail(SourceLoc where, const Argument& argument);
  bool awaitingKey() const;
  bool charge(size_t nodes, SourceLoc where);
  bool chargeAliasText(size_t bytes, SourceLoc where);
  void open(bool is_map, SourceLoc where, uint64_t anchor);
  void finish(ir::Value&& v, uint64_t anchor, bool is_null, bool counted = false);
  void acceptKey(Frame& parent, std::string_view text, SourceLoc key_loc);
  void rejectKey(Frame& parent, const ir::Value& key);
  void acceptValue(Frame& parent, ir::Value&& v, bool is_null);
  bool offerToSink(ir::Value& v);

  uint32_t file_;
  DiagnosticEmitter& diags_;
  YamlProblems policy_;
  std::vector<Frame> stack_;  ///< frames past depth_ are spare
  size_t depth_ = 0;
  std::unordered_map<uint64_t, Anchored> anchors_;
  std::optional<ir::Value> root_;
  size_t nodes_ = 0;
  size_t alias_bytes_ = 0;
  bool aborted_ = false;
  bool gave_up_ = false;
  ExprScalarReader exprs_;
  StatesSink* sink_ = nullptr;
};

}  // namespace smachac::frontend
