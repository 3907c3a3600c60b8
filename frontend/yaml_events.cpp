// yaml-cpp events → ir::Value.
#include "frontend/yaml_events.h"

#include <fmt/core.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <sstream>
#include <unordered_map>
#include <vector>

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

class ValueBuilder : public YAML::EventHandler {
 public:
  ValueBuilder(uint32_t file, DiagnosticEmitter& diags) : file_(file), diags_(diags) {}

  std::optional<ir::Value> take() {
    if (aborted_ || !root_) return std::nullopt;
    return std::move(root_);
  }
  bool aborted() const { return aborted_; }

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}

  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    ir::Value v = ir::Value::null(loc(mark));
    v.loc.length = 1;
    finish(std::move(v), anchor, /*is_null=*/true);
  }

  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    auto it = anchors_.find(anchor);
    if (it == anchors_.end()) {
      fail(DiagKind::YamlSyntax, loc(mark), "alias of an anchor that is not complete here");
      return;
    }
    if (!charge(it->second.nodes, loc(mark))) return;
    ir::Value copy = it->second.value;
    finish(std::move(copy), 0, false, /*counted=*/true);
  }

  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    bool quoted = tag == "!";
    SourceLoc l = loc(mark, value.size() + (quoted ? 2 : 0));
    if (awaitingKey()) {
      if (charge(1, l)) acceptKey(stack_.back(), value, loc(mark, value.size()));
      return;
    }
    ScalarResult r =
        resolveScalar(value, quoted ? ScalarStyle::Quoted : ScalarStyle::Plain, tag, l);
    if (r.int_overflow) diags_.emit(DiagKind::IntegerOutOfRange, l, value);
    finish(std::move(r.value), anchor, false);
  }

  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(ir::Value::list({}, loc(mark)), anchor);
  }
  void OnSequenceEnd() override { close(); }

  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(ir::Value::map({}, loc(mark)), anchor);
  }
  void OnMapEnd() override { close(); }

 private:
  /// A collection being built, and for maps the key waiting for its value.
  struct Frame {
    ir::Value value;
    YAML::anchor_t anchor = 0;
    bool has_key = false;
    bool key_valid = false;
    std::string key;
    SourceLoc key_loc;
  };

  SourceLoc loc(const YAML::Mark& mark, size_t length = 1) const {
    if (mark.is_null()) return {file_, 1, 1, 1};
    return {file_, static_cast<uint32_t>(mark.line + 1), static_cast<uint32_t>(mark.column + 1),
            static_cast<uint32_t>(std::max<size_t>(length, 1))};
  }

  void fail(DiagKind kind, SourceLoc l, const std::string& message) {
    if (!aborted_) diags_.emit(kind, l, message);
    aborted_ = true;
  }

  bool awaitingKey() const {
    return !stack_.empty() && stack_.back().value.isMap() && !stack_.back().has_key;
  }

  bool charge(size_t nodes, SourceLoc where) {
    nodes_ += nodes;
    if (nodes_ > kMaxYamlNodes) {
      fail(DiagKind::YamlTooComplex, where,
           fmt::format("YAML document expands to more than {} nodes (aliases included)",
                       kMaxYamlNodes));
    }
    return !aborted_;
  }

  void open(ir::Value container, YAML::anchor_t anchor) {
    if (aborted_) return;
    if (stack_.size() >= kMaxYamlDepth) {
      fail(DiagKind::YamlTooComplex, container.loc,
           fmt::format("YAML nested more than {} levels deep", kMaxYamlDepth));
      return;
    }
    stack_.push_back({std::move(container), anchor, false, false, {}, {}});
  }

  void close() {
    if (aborted_ || stack_.empty()) return;
    Frame frame = std::move(stack_.back());
    stack_.pop_back();
    finish(std::move(frame.value), frame.anchor, false);
  }

  /// Hands a finished value to its parent (or makes it the root), remembering anchors.
  void finish(ir::Value v, YAML::anchor_t anchor, bool is_null, bool counted = false) {
    if (aborted_) return;
    if (!counted && !charge(1, v.loc)) return;
    if (anchor != 0) anchors_[anchor] = {v, countNodes(v)};
    if (stack_.empty()) {
      root_ = std::move(v);
      return;
    }
    Frame& parent = stack_.back();
    if (parent.value.isList()) {
      parent.value.asList().push_back(std::move(v));
    } else if (!parent.has_key) {
      rejectKey(parent, v);
    } else {
      acceptValue(parent, std::move(v), is_null);
    }
  }

  void acceptKey(Frame& parent, const std::string& text, SourceLoc key_loc) {
    parent.has_key = true;
    parent.key_valid = true;
    parent.key = text;
    parent.key_loc = key_loc;
  }

  /// A key that is a collection (or null): only scalars can name an entry.
  void rejectKey(Frame& parent, const ir::Value& key) {
    parent.has_key = true;
    parent.key_valid = key.isNull();
    if (key.isNull()) {
      parent.key.clear();
      parent.key_loc = key.loc;
      return;
    }
    diags_.emit(DiagKind::NonScalarKey, key.loc, key.isMap() ? "a mapping" : "a sequence");
  }

  void acceptValue(Frame& parent, ir::Value v, bool is_null) {
    parent.has_key = false;
    if (!parent.key_valid) return;
    if (is_null && v.loc.line != parent.key_loc.line) v.loc = parent.key_loc;
    for (const ir::MapEntry& e : parent.value.asMap()) {
      if (e.key != parent.key) continue;
      diags_.emit(DiagKind::DuplicateKey, parent.key_loc, parent.key);
      diags_.note(e.key_loc, "first defined here");
      return;
    }
    parent.value.asMap().push_back({std::move(parent.key), parent.key_loc, std::move(v)});
  }

  struct Anchored {
    ir::Value value;
    size_t nodes = 0;
  };

  uint32_t file_;
  DiagnosticEmitter& diags_;
  std::vector<Frame> stack_;
  std::unordered_map<YAML::anchor_t, Anchored> anchors_;
  std::optional<ir::Value> root_;
  size_t nodes_ = 0;
  bool aborted_ = false;
};

SourceLoc markLoc(uint32_t file, const YAML::Mark& mark) {
  if (mark.is_null()) return {file, 0, 0, 1};
  return {file, static_cast<uint32_t>(std::max(mark.line, 0) + 1),
          static_cast<uint32_t>(std::max(mark.column, 0) + 1), 1};
}

}  // namespace

std::optional<ir::Value> buildYamlValue(uint32_t file, std::string_view text,
                                        DiagnosticEmitter& diags) {
  std::istringstream stream{std::string(text)};
  ValueBuilder builder(file, diags);
  try {
    YAML::Parser parser(stream);
    parser.HandleNextDocument(builder);
  } catch (const YAML::DeepRecursion& e) {
    diags.emit(DiagKind::YamlTooComplex, markLoc(file, e.mark),
               "YAML nested too deeply for the parser");
    return std::nullopt;
  } catch (const YAML::Exception& e) {
    diags.emit(DiagKind::YamlSyntax, markLoc(file, e.mark), e.msg);
    return std::nullopt;
  }
  std::optional<ir::Value> root = builder.take();
  if (!root && !builder.aborted()) return ir::Value::null({file, 1, 1, 1});
  return root;
}

}  // namespace smachac::frontend
