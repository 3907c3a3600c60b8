// The cursor context of half-typed YAML (lsp/yaml_context.h) and the tolerant reader under it
// (lsp/yaml_sketch.h). In the texts, `$` marks the cursor.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "frontend/yaml_loader.h"
#include "lsp/yaml_context.h"
#include "lsp/yaml_sketch.h"

namespace smachac::lsp {
namespace {

struct Probe {
  std::string text;
  YamlContext context;
};

Probe at(std::string_view marked) {
  size_t cursor = marked.find('$');
  REQUIRE(cursor != std::string_view::npos);
  std::string text = std::string(marked.substr(0, cursor)) + std::string(marked.substr(cursor + 1));
  return {text, yamlContextAt(text, cursor)};
}

std::string path(const Probe& probe) { return describePath(probe.context.path); }

std::string word(const Probe& probe) {
  const YamlContext& c = probe.context;
  return probe.text.substr(c.word_begin, c.word_end - c.word_begin);
}

constexpr const char* kState = "name: s\nstates:\n  - PICK:\n      template: X\n";

}  // namespace

TEST_CASE("a value in block style: the path ends with its key; the word is what is typed") {
  Probe p = at("name: s\nstates:\n  - PICK:\n      template: Pr$");
  CHECK(p.context.role == CursorRole::Value);
  CHECK(path(p) == "states/[0]/PICK/template");
  CHECK(p.context.prefix == "Pr");
  CHECK_FALSE(p.context.in_flow);
  Probe empty = at("name: s\nstates:\n  - PICK:\n      template: $");
  CHECK(empty.context.role == CursorRole::Value);
  CHECK(empty.context.prefix.empty());
  Probe no_space = at("template:$");
  CHECK(no_space.context.role == CursorRole::Value);
  CHECK(path(no_space) == "template");
}

TEST_CASE("a half-typed flow mapping: value after `key: `, key after `, `") {
  std::string base = kState;
  Probe value = at(base + "      transitions: {succeeded: $");
  CHECK(value.context.role == CursorRole::Value);
  CHECK(path(value) == "states/[0]/PICK/transitions/succeeded");
  CHECK(value.context.in_flow);
  Probe typed = at(base + "      transitions: {succeeded: DO$");
  CHECK(typed.context.prefix == "DO");
  Probe key = at(base + "      transitions: {succeeded: A, $");
  CHECK(key.context.role == CursorRole::Key);
  CHECK(path(key) == "states/[0]/PICK/transitions");
  Probe key_typed = at(base + "      transitions: {succeeded: A, ab$");
  CHECK(key_typed.context.role == CursorRole::Key);
  CHECK(key_typed.context.prefix == "ab");
  Probe first = at(base + "      transitions: {$");
  CHECK(first.context.role == CursorRole::Key);
  CHECK(path(first) == "states/[0]/PICK/transitions");
}

TEST_CASE("block mappings: a key being typed, a value on the next level") {
  std::string base = kState;
  Probe value = at(base + "      transitions:\n        succeeded: $");
  CHECK(value.context.role == CursorRole::Value);
  CHECK(path(value) == "states/[0]/PICK/transitions/succeeded");
  Probe key = at(base + "      transitions:\n        succ$");
  CHECK(key.context.role == CursorRole::Key);
  CHECK(path(key) == "states/[0]/PICK/transitions");
  CHECK(key.context.prefix == "succ");
  Probe state_key = at(base + "      outc$");
  CHECK(state_key.context.role == CursorRole::Key);
  CHECK(path(state_key) == "states/[0]/PICK");
}

TEST_CASE("a new state being typed: its name line, then its first key") {
  std::string base = kState;
  Probe name = at(base + "  - NEW$");
  CHECK(name.context.role == CursorRole::Item);
  CHECK(path(name) == "states/[1]");
  Probe after_colon = at(base + "  - NEW_STATE:$");
  CHECK(after_colon.context.role == CursorRole::Value);
  CHECK(path(after_colon) == "states/[1]/NEW_STATE");
  Probe blank = at(base + "  - NEW_STATE:\n      $");
  CHECK(blank.context.role == CursorRole::Key);
  CHECK(path(blank) == "states/[1]/NEW_STATE");
  Probe typed = at(base + "  - NEW_STATE:\n      tem$");
  CHECK(typed.context.role == CursorRole::Key);
  CHECK(path(typed) == "states/[1]/NEW_STATE");
  CHECK(typed.context.prefix == "tem");
}

TEST_CASE("a blank line is placed by its column") {
  std::string base = kState;
  CHECK(path(at(base + "      $")) == "states/[0]/PICK");
  CHECK(at(base + "      $").context.role == CursorRole::Key);
  CHECK(at(base + "  $").context.role == CursorRole::None);  // where `- ` would go
  Probe root = at(base + "$");
  CHECK(root.context.role == CursorRole::Key);
  CHECK(path(root).empty());
  Probe under = at("name: s\nstates:\n  - PICK:\n      transitions:\n        $\n      x: 1\n");
  CHECK(under.context.role == CursorRole::Key);
  CHECK(path(under) == "states/[0]/PICK/transitions");
  CHECK(at("template: X\n    $").context.role == CursorRole::None);  // under a whole value
}

TEST_CASE("the root: an empty document, a key being typed") {
  CHECK(at("$").context.role == CursorRole::Key);
  Probe typed = at("na$");
  CHECK(typed.context.role == CursorRole::Key);
  CHECK(path(typed).empty());
  CHECK(typed.context.prefix == "na");
  CHECK(at("# a comment\n$").context.role == CursorRole::Key);
}

TEST_CASE("list items in flow and block style") {
  Probe first = at("outcomes: [$");
  CHECK(first.context.role == CursorRole::Item);
  CHECK(path(first) == "outcomes/[0]");
  CHECK(first.context.in_flow);
  Probe second = at("outcomes: [done, $");
  CHECK(path(second) == "outcomes/[1]");
  Probe typed = at("outcomes: [done, fa$]");
  CHECK(path(typed) == "outcomes/[1]");
  CHECK(typed.context.prefix == "fa");
  Probe block = at("input_keys:\n  - a\n  - $");
  CHECK(block.context.role == CursorRole::Item);
  CHECK(path(block) == "input_keys/[1]");
  Probe block_typed = at("input_keys:\n  - a\n  - b$");
  CHECK(path(block_typed) == "input_keys/[1]");
  CHECK(block_typed.context.prefix == "b");
}

TEST_CASE("list indices of states, compact sequences, sub-scripts") {
  Probe second = at("states:\n  - A:\n      x: 1\n  - B:\n      template: $");
  CHECK(path(second) == "states/[1]/B/template");
  Probe compact = at("states:\n- A:\n    template: $");
  CHECK(path(compact) == "states/[0]/A/template");
  Probe sub_script = at("- GREET:\n    template: S$");
  CHECK(path(sub_script) == "[0]/GREET/template");
}

TEST_CASE("flow style state bodies and lists of states") {
  Probe body = at("states:\n  - A: {template: X, transitions: {succeeded: $");
  CHECK(body.context.role == CursorRole::Value);
  CHECK(path(body) == "states/[0]/A/transitions/succeeded");
  Probe list = at("states: [{A: {template: X}}, {B: {template: $");
  CHECK(path(list) == "states/[1]/B/template");
  Probe closed = at("states:\n  - A: {template: X}\n  - B: {outcomes: [a, $]}");
  CHECK(path(closed) == "states/[1]/B/outcomes/[1]");
}

TEST_CASE("a flow collection across lines, and one whose bracket is not typed yet") {
  Probe continued = at("transitions: {succeeded: A,\n    $");
  CHECK(continued.context.role == CursorRole::Key);
  CHECK(path(continued) == "transitions");
  CHECK(continued.context.in_flow);
  std::string base = kState;
  Probe unclosed = at(base + "      transitions: {succeeded: \n      $");
  CHECK(unclosed.context.role == CursorRole::Key);
  CHECK(path(unclosed) == "states/[0]/PICK");
  CHECK_FALSE(unclosed.context.in_flow);
  Probe next = at(base + "      transitions: {succeeded: \n      outcomes: [$");
  CHECK(path(next) == "states/[0]/PICK/outcomes/[0]");
}

TEST_CASE("comments, quotes and code") {
  CHECK(at("name: x  # a com$").context.in_comment);
  CHECK(at("# $").context.in_comment);
  CHECK_FALSE(at("name: x#y$").context.in_comment);  // `#` inside a scalar
  Probe quoted = at("template: 'Pri$ntX'");
  CHECK(quoted.context.role == CursorRole::Value);
  CHECK(quoted.context.quoted);
  CHECK(quoted.context.prefix == "Pri");
  CHECK(word(quoted) == "PrintX");
  Probe after_quote = at("template: 'X' $");
  CHECK(after_quote.context.role == CursorRole::None);
  CHECK(at("callbacks: {x: '`lambda ud: u$").context.in_code);
  CHECK(at("callbacks: {x: `lam$").context.in_code);
  CHECK(at("note: \"a: b$").context.quoted);
}

TEST_CASE("after a whole scalar, and in block scalars, nothing is typed") {
  CHECK(at("template: Foo $").context.role == CursorRole::None);
  CHECK(at("transitions: {a: B $").context.role == CursorRole::None);
  CHECK(at("description: |\n  some text $").context.role == CursorRole::None);
  Probe after = at("description: |\n  text\n$");
  CHECK(after.context.role == CursorRole::Key);
  Probe sibling = at("- text: |\n    line\n  templ$");
  CHECK(sibling.context.role == CursorRole::Key);
  CHECK(path(sibling) == "[0]");
}

TEST_CASE("the word extends over what follows the cursor, within the scalar") {
  Probe key = at("templ$ate: X");
  CHECK(key.context.role == CursorRole::Key);
  CHECK(key.context.prefix == "templ");
  CHECK(word(key) == "template");
  Probe flow = at("transitions: {succeeded: $DONE}");
  CHECK(flow.context.prefix.empty());
  CHECK(word(flow) == "DONE");
  Probe utf8 = at("name: caf\xC3\xA9$");
  CHECK(utf8.context.prefix == "caf\xC3\xA9");
  Probe dir = at("script: sub/gr$");
  CHECK(dir.context.prefix == "sub/gr");
}

TEST_CASE("tags and anchors do not hide the value") {
  Probe tagged = at("callbacks: {done: !expr $");
  CHECK(tagged.context.role == CursorRole::Value);
  CHECK(path(tagged) == "callbacks/done");
}

namespace {

/// Keys, key locations, list sizes and scalar locations of two trees agree (the sketch keeps
/// scalars as strings, so values are compared by position only).
void checkSameShape(const ir::Value& sketch, const ir::Value& parsed, const std::string& where) {
  INFO(where);
  CHECK(sketch.loc.line == parsed.loc.line);
  // A portable expression (`!expr 'x'`) is located at its text, inside the quotes.
  if (parsed.kind() != ir::ValueKind::Expression) CHECK(sketch.loc.column == parsed.loc.column);
  if (parsed.isMap()) {
    REQUIRE(sketch.isMap());
    REQUIRE(sketch.asMap().size() == parsed.asMap().size());
    for (size_t i = 0; i < parsed.asMap().size(); ++i) {
      const ir::MapEntry& a = sketch.asMap()[i];
      const ir::MapEntry& b = parsed.asMap()[i];
      CHECK(a.key == b.key);
      CHECK(a.key_loc == b.key_loc);
      checkSameShape(a.value, b.value, where + "/" + b.key);
    }
  } else if (parsed.isList()) {
    REQUIRE(sketch.isList());
    REQUIRE(sketch.asList().size() == parsed.asList().size());
    for (size_t i = 0; i < parsed.asList().size(); ++i) {
      checkSameShape(sketch.asList()[i], parsed.asList()[i],
                     where + "/[" + std::to_string(i) + "]");
    }
  } else {
    CHECK_FALSE(sketch.isMap());
    CHECK_FALSE(sketch.isList());
  }
}

}  // namespace

TEST_CASE("on the example scripts, the sketch has the parsed tree's shape and locations") {
  namespace fs = std::filesystem;
  int compared = 0;
  for (const char* dir : {"examples/core", "tests/lsp/sessions/scripts"}) {
    for (const fs::directory_entry& entry :
         fs::recursive_directory_iterator(fs::path(SMACHAC_SOURCE_DIR) / dir)) {
      if (entry.path().extension() != ".yml") continue;
      std::ifstream in(entry.path());
      std::stringstream text;
      text << in.rdbuf();
      SourceManager sources;
      uint32_t file = sources.addFile(entry.path().string(), text.str());
      DiagnosticEmitter diags;
      std::optional<ir::Value> parsed = frontend::parseYaml(file, sources, diags);
      if (!parsed) continue;
      checkSameShape(sketchYaml(text.str(), file), *parsed, entry.path().string());
      ++compared;
    }
  }
  CHECK(compared > 5);
}

TEST_CASE("the sketch of a half-typed script keeps what is around the broken line") {
  ir::Value root = sketchYaml(
      "name: s\nstates:\n  - A:\n      transitions: {succeeded: \n  - B:\n      templ\n", 1);
  REQUIRE(root.isMap());
  const ir::Value* states = root.find("states");
  REQUIRE(states);
  REQUIRE(states->asList().size() == 2);
  const ir::Value* a = states->asList()[0].find("A");
  REQUIRE(a);
  CHECK(a->find("transitions")->find("succeeded"));
  const ir::Value* b = states->asList()[1].find("B");
  REQUIRE(b);
  REQUIRE(b->isMap());
  CHECK(b->asMap().front().key == "templ");
  CHECK(b->asMap().front().key_loc == SourceLoc{1, 6, 7, 5});
}

}  // namespace smachac::lsp
