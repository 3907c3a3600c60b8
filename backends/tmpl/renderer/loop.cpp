// `for` loops: lazy iteration (a list appended to during the loop is seen, a dict changed
// during the loop is an error, like Python), loop filters, `else`, and the `loop` object with
// Jinja2's LoopContext attributes (index, first, last, length, cycle, changed, ...).
#include "backends/tmpl/error.h"
#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/string_ops.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

// Yields the items of an iterable value one at a time.
class Source {
 public:
  explicit Source(Value v) : value_(std::move(v)) {
    switch (value_.kind()) {
      case Kind::Undefined:
        done_ = true;
        break;
      case Kind::List:
      case Kind::Tuple:
        break;
      case Kind::Dict:
        shape_ = value_.dict().shape();
        break;
      default:
        snapshot_ = iterate(value_);
    }
  }

  bool next(Value& out) {
    if (done_) return false;
    switch (value_.kind()) {
      case Kind::List:
      case Kind::Tuple:
        return take(value_.list().items(), out);
      case Kind::Dict:
        if (value_.dict().shape() != shape_) fail("dictionary changed size during iteration");
        if (index_ >= value_.dict().size()) return false;
        out = value_.dict().entries()[index_++].first;
        return true;
      default:
        return take(snapshot_, out);
    }
  }

 private:
  bool take(const std::vector<Value>& items, Value& out) {
    if (index_ >= items.size()) return false;
    out = items[index_++];
    return true;
  }

  Value value_;
  std::vector<Value> snapshot_;
  size_t index_ = 0;
  uint64_t shape_ = 0;
  bool done_ = false;
};

// The filtered item stream with look-ahead, which `loop.last`/`length` need: one item held
// by `peek` (`loop.last`, no allocation), or all the rest buffered by `remaining`.
class Feed {
 public:
  Feed(Exec& ex, Site& site, const ForStmt& node, Value iterable)
      : ex_(ex), site_(site), node_(node), source_(std::move(iterable)) {}

  bool next(Value& out) {
    if (head_ < buffer_.size()) {
      out = std::move(buffer_[head_++]);
      return true;
    }
    if (has_peeked_) {
      has_peeked_ = false;
      out = std::move(peeked_);
      return true;
    }
    return fetch(out);
  }

  bool peek(Value& out) {
    if (head_ < buffer_.size()) {
      out = buffer_[head_];
      return true;
    }
    if (!has_peeked_) {
      Value v;
      if (!fetch(v)) return false;
      peeked_ = std::move(v);
      has_peeked_ = true;
    }
    out = peeked_;
    return true;
  }

  /// Whether an item follows (`loop.last`), fetching it ahead without copying it out.
  bool hasMore() {
    if (head_ < buffer_.size() || has_peeked_) return true;
    has_peeked_ = fetch(peeked_);
    if (!has_peeked_) peeked_ = Value();
    return has_peeked_;
  }

  size_t remaining() {
    if (has_peeked_) {  // the buffer is consumed: the held item comes first
      buffer_.push_back(std::move(peeked_));
      has_peeked_ = false;
    }
    Value v;
    while (fetch(v)) buffer_.push_back(std::move(v));
    return buffer_.size() - head_;
  }

 private:
  bool fetch(Value& out) {
    while (source_.next(out)) {
      if (!node_.filter || accepts(out)) return true;
    }
    return false;
  }

  bool accepts(const Value& item) {
    if (!test_frame_)
      test_frame_ = Frame::make(site_.frame, &site_.frame->context(), node_.test_frame.num_slots);
    initFrame(*test_frame_, node_.test_frame, ex_.registry);
    bindTarget(*test_frame_, node_.target, item, node_.test_target_slots.data());
    Site test_site = site_.inner(test_frame_.get());
    return truthy(eval(ex_, test_site, node_.filter));
  }

  Exec& ex_;
  Site& site_;
  const ForStmt& node_;
  Source source_;
  std::vector<Value> buffer_;  // items fetched ahead; the first `head_` are consumed
  size_t head_ = 0;
  Value peeked_;  // the item `peek` fetched, once the buffer is consumed
  bool has_peeked_ = false;
  Ref<Frame> test_frame_;
};

// Jinja2's LoopContext over a Feed, or over the pairs of a sorted-items loop, which it reads
// by index: `last`, `length`, `previtem` and `nextitem` of a pair need no tuple made for each
// item (the tuples `previtem`/`nextitem` return are made once per pair, when first asked for).
class LoopObject final : public Object {
 public:
  explicit LoopObject(Feed* feed) : feed_(feed) {}
  explicit LoopObject(const std::vector<DictObject::Entry>* pairs) : pairs_(pairs) {}

  void advance(const Value& item) {
    ++index0_;
    previous_ = current_;
    current_ = item;
  }
  void advancePair() { ++index0_; }
  void finish() {
    length_ = index0_ + 1;
    if (pairs_ && index0_ > 0) keepPreviousPair();
    feed_ = nullptr;
    pairs_ = nullptr;
  }

  std::string_view typeName() const override { return "LoopContext"; }
  void repr(std::string& out) const override {
    out += "<LoopContext " + std::to_string(index0_ + 1) + "/" + std::to_string(length()) + ">";
  }
  bool getAttr(std::string_view name, Value& out) const override;
  bool iterate(std::vector<Value>&) const override { return false; }
  Value cycle(const CallArgs& args) const {
    if (args.positional.empty()) fail("no items for cycling given");
    return args.positional[static_cast<size_t>(index0_) % args.positional.size()];
  }
  Value changed(const CallArgs& args) {
    Value current = Value::newTuple({args.positional.begin(), args.positional.end()});
    if (has_changed_ && equals(last_changed_, current)) return Value::boolean(false);
    has_changed_ = true;
    last_changed_ = current;
    return Value::boolean(true);
  }

 private:
  int64_t length() const {
    if (length_ < 0 && pairs_) length_ = static_cast<int64_t>(pairs_->size());
    if (length_ < 0 && feed_) length_ = index0_ + 1 + static_cast<int64_t>(feed_->remaining());
    return length_ < 0 ? index0_ + 1 : length_;
  }
  bool hasNext(Value* out) const {
    if (pairs_) {
      auto next = static_cast<size_t>(index0_ + 1);
      if (next >= pairs_->size()) return false;
      if (out) *out = pairAt(next);
      return true;
    }
    if (!feed_) return false;
    if (!out) return feed_->hasMore();
    return feed_->peek(*out);
  }
  Value previousItem() const {
    if (pairs_) return index0_ > 0 ? pairAt(static_cast<size_t>(index0_ - 1)) : Value();
    if (!previous_pair_.first.isUndefined()) {  // a pair loop that ended: its tuple, once
      previous_ = Value::newTuple({previous_pair_.first, previous_pair_.second});
      previous_pair_ = {};
    }
    return previous_;
  }
  // What `previtem` needs once the loop has ended (the object may outlive it): the tuple of
  // the previous pair if it was made, else the pair, made a tuple only if asked for.
  void keepPreviousPair() {
    auto i = static_cast<size_t>(index0_ - 1);
    if (i < pair_tuples_.size() && !pair_tuples_[i].isUndefined()) {
      previous_ = pair_tuples_[i];
    } else {
      previous_pair_ = (*pairs_)[i];
    }
  }
  // The tuple of pair `i`, the same object each time it is asked for.
  const Value& pairAt(size_t i) const {
    if (pair_tuples_.empty()) pair_tuples_.resize(pairs_->size());
    Value& tuple = pair_tuples_[i];
    if (tuple.isUndefined()) tuple = Value::newTuple({(*pairs_)[i].first, (*pairs_)[i].second});
    return tuple;
  }

  Feed* feed_ = nullptr;
  const std::vector<DictObject::Entry>* pairs_ = nullptr;
  mutable std::vector<Value> pair_tuples_;
  int64_t index0_ = -1;
  mutable int64_t length_ = -1;
  Value current_;
  mutable Value previous_;  // unset until the second item (as before: the first has none)
  mutable DictObject::Entry previous_pair_;  // see keepPreviousPair
  bool has_changed_ = false;
  Value last_changed_;
};

// Ends the loop object's view of its items when the loop ends (it may outlive the loop).
struct LoopFinisher {
  LoopObject* loop;
  ~LoopFinisher() {
    if (loop) loop->finish();
  }
};

class LoopMethod final : public Object {
 public:
  LoopMethod(Ref<LoopObject> loop, bool cycle) : loop_(std::move(loop)), cycle_(cycle) {}
  std::string_view typeName() const override { return "method"; }
  bool isCallable() const override { return true; }
  Value call(Exec&, const CallArgs& args) const override {
    return cycle_ ? loop_->cycle(args) : loop_->changed(args);
  }

 private:
  Ref<LoopObject> loop_;
  bool cycle_;
};

bool LoopObject::getAttr(std::string_view name, Value& out) const {
  int64_t index = index0_ + 1;
  if (name == "index")
    out = Value::integer(index);
  else if (name == "index0")
    out = Value::integer(index0_);
  else if (name == "first")
    out = Value::boolean(index0_ == 0);
  else if (name == "last")
    out = Value::boolean(!hasNext(nullptr));
  else if (name == "length")
    out = Value::integer(length());
  else if (name == "revindex")
    out = Value::integer(length() - index0_);
  else if (name == "revindex0")
    out = Value::integer(length() - index);
  else if (name == "depth")
    out = Value::integer(1);
  else if (name == "depth0")
    out = Value::integer(0);
  else if (name == "previtem")
    out = previousItem();
  else if (name == "nextitem") {
    if (!hasNext(&out)) out = Value::undefinedHint("there is no next item");
  } else if (name == "cycle" || name == "changed") {
    out = Value::object(new LoopMethod(const_cast<LoopObject*>(this), name == "cycle"));
  } else {
    return false;
  }
  return true;
}

void execElse(Exec& ex, Site& site, const ForStmt& node) {
  FrameHolder else_frame(ex, site.frame, &site.frame->context(), node.else_frame);
  initFrame(*else_frame, node.else_frame, ex.registry);
  Site else_site = site.inner(else_frame.get());
  execBody(ex, else_site, node.orelse);
}

bool hasNoArgs(const ArgList& args) {
  return args.args.empty() && args.kwargs.empty() && !args.dyn_args && !args.dyn_kwargs;
}

// `for k, v in name.items() | sort` (the built-in sort, no arguments, no loop filter).
bool isSortedItemsLoop(const ForStmt& node) {
  if (node.filter || node.target->kind != ExprKind::Tuple) return false;
  const auto& names = static_cast<const SeqExpr*>(node.target)->items;
  if (names.size() != 2 || names[0]->kind != ExprKind::Name || names[1]->kind != ExprKind::Name)
    return false;
  if (node.iter->kind != ExprKind::Filter) return false;
  const auto* sort = static_cast<const FilterExpr*>(node.iter);
  if (sort->def != builtinTable().filter("sort") || !hasNoArgs(sort->args)) return false;
  if (!sort->input || sort->input->kind != ExprKind::Call) return false;
  const auto* call = static_cast<const CallExpr*>(sort->input);
  if (call->callee->kind != ExprKind::Getattr || !hasNoArgs(call->args)) return false;
  const auto* items = static_cast<const GetattrExpr*>(call->callee);
  return *items->attr == "items" && items->object->kind == ExprKind::Name;
}

// The items of a sorted-items loop over a dict, as `d.items() | sort` makes them: the
// entries in sorted order (a fault of the sort located at the filter), charged like the
// sorted list.
std::vector<DictObject::Entry> sortedEntries(Exec& ex, const ForStmt& node, const Value& dict) {
  std::vector<size_t> order;
  try {
    order = sortedItemsOrder(dict.dict());
  } catch (const Fault& fault) {
    throw ex.tmpl->error(node.iter->pos, fault.message());
  }
  std::vector<DictObject::Entry> entries;
  entries.reserve(order.size());
  for (size_t i : order) entries.push_back(dict.dict().entries()[i]);
  return entries;
}

void runLoop(Exec& ex, Site& site, const ForStmt& node, Value iterable) {
  if (!iterable.isObject() && !isIterable(iterable)) {
    fail("`" + std::string(typeName(iterable)) + "` object is not iterable");
  }
  Feed feed(ex, site, node, iterable);
  FrameHolder frame(ex, site.frame, &site.frame->context(), node.loop_frame);
  Ref<LoopObject> loop = node.loop_slot >= 0 ? new LoopObject(&feed) : nullptr;
  LoopFinisher finisher{loop.get()};
  Site inner = site.inner(frame.get());
  bool iterated = false;
  Value item;
  while (feed.next(item)) {
    ex.step();
    iterated = true;
    initFrame(*frame, node.loop_frame, ex.registry);
    bindTarget(*frame, node.target, item, nullptr);
    if (loop) {
      loop->advance(item);
      frame->local(static_cast<uint16_t>(node.loop_slot)) = Value::object(loop.get());
    }
    execBody(ex, inner, node.body);
  }
  if (!iterated && !node.orelse.empty()) execElse(ex, site, node);
}

// The body of a sorted-items loop for each pair, bound to the two names without a tuple.
void runPairs(Exec& ex, Site& site, const ForStmt& node,
              const std::vector<DictObject::Entry>& pairs) {
  const auto& names = static_cast<const SeqExpr*>(node.target)->items;
  SlotRef key = static_cast<const NameExpr*>(names[0])->ref;
  SlotRef value = static_cast<const NameExpr*>(names[1])->ref;
  FrameHolder frame(ex, site.frame, &site.frame->context(), node.loop_frame);
  Ref<LoopObject> loop = node.loop_slot >= 0 ? new LoopObject(&pairs) : nullptr;
  LoopFinisher finisher{loop.get()};
  Site inner = site.inner(frame.get());
  for (const auto& [k, v] : pairs) {
    ex.step();
    initFrame(*frame, node.loop_frame, ex.registry);
    frame->slot(key) = k;
    frame->slot(value) = v;
    if (loop) {
      loop->advancePair();
      frame->local(static_cast<uint16_t>(node.loop_slot)) = Value::object(loop.get());
    }
    execBody(ex, inner, node.body);
  }
  if (pairs.empty() && !node.orelse.empty()) execElse(ex, site, node);
}

// A sorted-items loop over a dict (false for anything else: the loop runs as written).
bool runSortedItems(Exec& ex, Site& site, const ForStmt& node) {
  if (node.sorted_items < 0) node.sorted_items = isSortedItemsLoop(node) ? 1 : 0;
  if (node.sorted_items == 0) return false;
  const auto* call = static_cast<const CallExpr*>(static_cast<const FilterExpr*>(node.iter)->input);
  const Expr* object = static_cast<const GetattrExpr*>(call->callee)->object;
  const Value& self = site.frame->slot(static_cast<const NameExpr*>(object)->ref);
  if (!self.isDict()) return false;
  std::vector<DictObject::Entry> pairs = sortedEntries(ex, node, self);
  chargeWork(pairs.size() * sizeof(Value));  // the sorted list
  runPairs(ex, site, node, pairs);
  return true;
}

}  // namespace

void execFor(Exec& ex, Site& site, const ForStmt& node) {
  if (runSortedItems(ex, site, node)) return;
  runLoop(ex, site, node, eval(ex, site, node.iter));
}

}  // namespace smachac::tmpl
