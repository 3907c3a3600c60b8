// YAML events → ir::Value.
#include "frontend/yaml_value_builder.h"

#include <algorithm>
#include <iterator>

#include "frontend/scalar.h"

namespace smachac::frontend {
namespace {

size_t countNodes(const ir::Value& v) {
  size_t n = 1;
  if (v.isList()) {
    for (const ir::Value& item : v.asList()) n += countNodes(item);
  } else if (v.isMap()) {
    for (const ir::MapEntry& e : v.asMap()) n += countNodes(e.value);
  }
  return n;
}

size_t countTextBytes(const ir::Value& v) {
  if (v.isString()) return v.asString().size();
  size_t n = 0;
  if (v.isList()) {
    for (const ir::Value& item : v.asList()) n += countTextBytes(item);
  } else if (v.isMap()) {
    for (const ir::MapEntry& e : v.asMap()) n += e.key.size() + countTextBytes(e.value);
  }
  return n;
}

/// The items of a frame's buffer in a vector of their exact size; the buffer keeps its
/// capacity for the next collection.
template <typename Item>
std::vector<Item> takeExact(std::vector<Item>& buffer) {
  std::vector<Item> exact(std::make_move_iterator(buffer.begin()),
                          std::make_move_iterator(buffer.end()));
  buffer.clear();
  return exact;
}

}  // namespace

std::optional<ir::Value> YamlValueBuilder::take() {
  if (aborted_ || !root_) return std::nullopt;
  return std::move(root_);
}

void YamlValueBuilder::onNull(YamlMark mark, uint64_t anchor) {
  ir::Value v = ir::Value::null(loc(mark));
  v.loc.length = 1;
  finish(std::move(v), anchor, /*is_null=*/true);
}

void YamlValueBuilder::onAlias(YamlMark mark, uint64_t anchor) {
  auto it = anchors_.find(anchor);
  if (it == anchors_.end()) {
    fail<DiagKind::YamlSyntax>(loc(mark),
                               ForeignMessage("alias of an anchor that is not complete here"));
    return;
  }
  if (!charge(it->second.nodes, loc(mark))) return;
  if (!chargeAliasText(it->second.bytes, loc(mark))) return;
  finish(ir::Value(it->second.value), 0, false, /*counted=*/true);
}

void YamlValueBuilder::onScalar(YamlMark mark, std::string_view tag, uint64_t anchor,
                                std::string_view value) {
  bool quoted = tag == "!";
  SourceLoc l = loc(mark, value.size() + (quoted ? 2 : 0));
  if (awaitingKey()) {
    if (charge(1, l)) acceptKey(stack_[depth_ - 1], value, loc(mark, value.size()));
    return;
  }
  if (tag == kPortableExprTag) {
    finish(portableExpr(mark, value), anchor, false);
    return;
  }
  ScalarResult r = resolveScalar(value, quoted ? ScalarStyle::Quoted : ScalarStyle::Plain, tag, l);
  if (r.int_overflow) report<DiagKind::IntegerOutOfRange>(l, value);
  finish(std::move(r.value), anchor, false);
}

ir::Value YamlValueBuilder::portableExpr(YamlMark mark, std::string_view value) {
  std::optional<ExprScalarError> error;
  ir::Value v = exprs_.read(mark.line, mark.column, value, error);
  if (error) report<DiagKind::ExprSyntax>(error->loc, error->message);
  return v;
}

void YamlValueBuilder::onSequenceStart(YamlMark mark, uint64_t anchor) {
  open(false, loc(mark), anchor);
}

void YamlValueBuilder::onMapStart(YamlMark mark, uint64_t anchor) { open(true, loc(mark), anchor); }

void YamlValueBuilder::onCollectionEnd() {
  if (aborted_ || depth_ == 0) return;
  Frame& frame = stack_[--depth_];
  finish(frame.is_map ? ir::Value::map(takeExact(frame.entries), frame.loc)
                      : ir::Value::list(takeExact(frame.items), frame.loc),
         frame.anchor, false);
}

SourceLoc YamlValueBuilder::loc(YamlMark mark, size_t length) const {
  if (mark.line < 0) return {file_, 1, 1, 1};
  return {file_, static_cast<uint32_t>(mark.line + 1), static_cast<uint32_t>(mark.column + 1),
          static_cast<uint32_t>(std::max<size_t>(length, 1))};
}

template <DiagKind Kind, typename... Args>
void YamlValueBuilder::report(SourceLoc where, const Args&... args) {
  if (policy_ == YamlProblems::GiveUp) {
    gave_up_ = true;
    aborted_ = true;
    return;
  }
  diags_.emit<Kind>(where, args...);
}

template <DiagNoteKind Note>
void YamlValueBuilder::note(SourceLoc where) {
  if (policy_ == YamlProblems::Report) diags_.note<Note>(where);
}

template <DiagKind Kind, typename Argument>
void YamlValueBuilder::fail(SourceLoc where, const Argument& argument) {
  if (!aborted_) report<Kind>(where, argument);
  aborted_ = true;
}

bool YamlValueBuilder::awaitingKey() const {
  return depth_ > 0 && stack_[depth_ - 1].is_map && !stack_[depth_ - 1].has_key;
}

bool YamlValueBuilder::charge(size_t nodes, SourceLoc where) {
  nodes_ += nodes;
  if (nodes_ > kMaxYamlNodes) {
    fail<DiagKind::YamlTooComplex>(where, Numbered{YamlLimit::Nodes, kMaxYamlNodes});
  }
  return !aborted_;
}

bool YamlValueBuilder::chargeAliasText(size_t bytes, SourceLoc where) {
  alias_bytes_ += bytes;
  if (alias_bytes_ > kMaxYamlAliasBytes) {
    fail<DiagKind::YamlTooComplex>(where,
                                   Numbered{YamlLimit::AliasMebibytes, kMaxYamlAliasBytes >> 20});
  }
  return !aborted_;
}

void YamlValueBuilder::open(bool is_map, SourceLoc where, uint64_t anchor) {
  if (aborted_) return;
  if (depth_ >= kMaxYamlDepth) {
    fail<DiagKind::YamlTooComplex>(where, Numbered{YamlLimit::Depth, kMaxYamlDepth});
    return;
  }
  if (depth_ == stack_.size()) stack_.emplace_back();
  Frame& frame = stack_[depth_++];
  frame.is_map = is_map;
  frame.loc = where;
  frame.anchor = anchor;
  frame.has_key = false;
  frame.key_valid = false;
}

/// Hands a finished value to its parent (or makes it the root), remembering anchors.
void YamlValueBuilder::finish(ir::Value&& v, uint64_t anchor, bool is_null, bool counted) {
  if (aborted_) return;
  if (!counted && !charge(1, v.loc)) return;
  if (anchor != 0) anchors_[anchor] = {v, countNodes(v), countTextBytes(v)};
  if (depth_ == 0) {
    root_ = std::move(v);
    return;
  }
  if (depth_ == 2 && sink_ && offerToSink(v)) return;
  Frame& parent = stack_[depth_ - 1];
  if (!parent.is_map) {
    parent.items.push_back(std::move(v));
  } else if (!parent.has_key) {
    rejectKey(parent, v);
  } else {
    acceptValue(parent, std::move(v), is_null);
  }
}

/// An item of the root mapping's `states` list goes to the sink, if it takes it.
bool YamlValueBuilder::offerToSink(ir::Value& v) {
  const Frame& root = stack_[0];
  const Frame& list = stack_[1];
  if (!root.is_map || list.is_map || !root.has_key || !root.key_valid || root.key != "states") {
    return false;
  }
  return sink_->take(v, {root.loc, root.entries, root.key_loc, list.loc});
}

void YamlValueBuilder::acceptKey(Frame& parent, std::string_view text, SourceLoc key_loc) {
  parent.has_key = true;
  parent.key_valid = true;
  parent.key.assign(text);
  parent.key_loc = key_loc;
}

/// A key that is a collection (or null): only scalars can name an entry.
void YamlValueBuilder::rejectKey(Frame& parent, const ir::Value& key) {
  parent.has_key = true;
  parent.key_valid = key.isNull();
  if (key.isNull()) {
    parent.key.clear();
    parent.key_loc = key.loc;
    return;
  }
  report<DiagKind::NonScalarKey>(key.loc, key.isMap() ? "a mapping" : "a sequence");
}

void YamlValueBuilder::acceptValue(Frame& parent, ir::Value&& v, bool is_null) {
  parent.has_key = false;
  if (!parent.key_valid) return;
  if (is_null && v.loc.line != parent.key_loc.line) v.loc = parent.key_loc;
  for (const ir::MapEntry& e : parent.entries) {
    if (e.key != parent.key) continue;
    report<DiagKind::DuplicateKey>(parent.key_loc, parent.key);
    note<DiagNoteKind::FirstDefinedHere>(e.key_loc);
    return;
  }
  parent.entries.push_back(ir::MapEntry{std::move(parent.key), parent.key_loc, std::move(v)});
}

}  // namespace smachac::frontend
