// Completion, document symbols and folding through their handlers, on documents held by a
// Workspace: what is offered where, UTF-16 ranges, and that no text (half-typed, cut anywhere,
// absurdly nested) makes them fail. In the texts, `$` marks the cursor.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lsp/features/features.h"
#include "lsp/positions.h"
#include "lsp/yaml_context.h"

namespace smachac::lsp {
namespace {

constexpr const char* kUri = "untitled:completion-test";

class Editor {
 public:
  Editor() : workspace_(Settings{}) {}

  /// Opens (or replaces) the document with `marked` without its `$`; the cursor's position.
  Position type(std::string_view marked) {
    size_t cursor = marked.find('$');
    std::string text(marked.substr(0, cursor));
    if (cursor != std::string_view::npos) text += marked.substr(cursor + 1);
    workspace_.documents().open(kUri, text, ++version_);
    workspace_.opened(kUri);
    return LineIndex(text).positionOf(cursor == std::string_view::npos ? 0 : cursor);
  }

  Json complete(Position at) {
    return completion(workspace_, {{"textDocument", {{"uri", kUri}}}, {"position", toJson(at)}});
  }

  std::vector<std::string> labels(std::string_view marked) {
    Json reply = complete(type(marked));
    std::vector<std::string> labels;
    for (const Json& item : reply.at("items")) labels.push_back(item.at("label"));
    return labels;
  }

  Json symbols() { return documentSymbol(workspace_, {{"textDocument", {{"uri", kUri}}}}); }
  Json folds() { return foldingRange(workspace_, {{"textDocument", {{"uri", kUri}}}}); }

 private:
  Workspace workspace_;
  int64_t version_ = 0;
};

using Labels = std::vector<std::string>;

constexpr const char* kScript = R"(name: s
template: Base
outcomes: [finished, failed]
userdata: {limit: 3}
states:
  - FIRST:
      template: PrintUserdataState
      input_keys: [limit]
      transitions: {succeeded: SECOND}
  - SECOND:
      template: LogState
      text: hi
      transitions: {done: finished}
)";

std::string withLine(const std::string& line) { return std::string(kScript) + line; }

}  // namespace

TEST_CASE("transition targets are the same whether the script parses or not") {
  Editor editor;
  Labels expected = {"FIRST", "SECOND", "finished", "failed"};
  std::string parsing = kScript;
  parsing.replace(parsing.find("SECOND}"), 6, "$SECOND");
  CHECK(editor.labels(parsing) == expected);
  CHECK(editor.labels(withLine("  - THIRD:\n      transitions: {done: $")) ==
        Labels{"FIRST", "SECOND", "THIRD", "finished", "failed"});
}

TEST_CASE("transition keys: declared outcomes, else the template's, without a transition") {
  Editor editor;
  CHECK(editor.labels(withLine(
            "  - THIRD:\n      outcomes: [a, b]\n      transitions: {a: FIRST, $")) == Labels{"b"});
  CHECK(editor.labels(
            withLine("  - THIRD:\n      template: LogState\n      transitions:\n        $")) ==
        Labels{"done"});
}

TEST_CASE("state keys leave out what the state has; shorthands count as their longhand") {
  Editor editor;
  Labels keys =
      editor.labels(withLine("  - THIRD:\n      T: LogState\n      t: {done: FIRST}\n      $"));
  CHECK(keys.front() == "text");  // LogState's required variable
  CHECK(std::find(keys.begin(), keys.end(), "template") == keys.end());
  CHECK(std::find(keys.begin(), keys.end(), "transitions") == keys.end());
  CHECK(std::find(keys.begin(), keys.end(), "outcomes") != keys.end());
}

TEST_CASE("outcomes a container lacks: its states' targets that are not states") {
  Editor editor;
  std::string text = kScript;
  text.replace(text.find("[finished, failed]"), 18, "[$]");
  text.replace(text.find("{done: finished}"), 16, "{done: stopped}");
  CHECK(editor.labels(text) == Labels{"stopped"});
}

TEST_CASE("userdata keys in scope, nearest first, without those listed") {
  Editor editor;
  std::string text = withLine(
      "  - WORK:\n      template: StateMachine\n      outcomes: [ok]\n      input_keys: [limit]\n"
      "      userdata: {step: 1}\n      states:\n        - A:\n            template: "
      "CallbacksState\n"
      "            output_keys: [x]\n            remapping: {x: y}\n        - B:\n"
      "            template: PrintUserdataState\n            input_keys: [step, $]\n");
  CHECK(editor.labels(text) == Labels{"limit", "y"});
}

TEST_CASE("nothing in comments, in code, after a whole value, on a dash of the states list") {
  Editor editor;
  CHECK(editor.labels(withLine("  # a comment $")).empty());
  CHECK(editor.labels(withLine("  - X:\n      callbacks: {a: '`lambda ud: $")).empty());
  CHECK(editor.labels(withLine("  - X:\n      template: LogState $")).empty());
  CHECK(editor.labels(withLine("  - $")).empty());
}

TEST_CASE("ranges count UTF-16 units; a key is inserted with its colon") {
  Editor editor;
  // `\xF0\x9F\x98\x80` is one character of 2 UTF-16 units, `\xC3\xBC` one of 1.
  Position at =
      editor.type("name: s\nstates:\n  - A:\n      transitions: {\xF0\x9F\x98\x80\xC3\xBC: $xy}\n");
  CHECK(at == Position{3, 25});
  Json value = editor.complete(at).at("items");
  REQUIRE(value.size() == 1);
  CHECK(value[0].at("textEdit").at("range") == toJson(Range{{3, 25}, {3, 27}}));
  CHECK(value[0].at("textEdit").at("newText") == "A");
  Json key = editor.complete(editor.type("name: s\n\xC3\xA9t$\n")).at("items");
  REQUIRE(!key.empty());
  CHECK(key[0].at("textEdit").at("range") == toJson(Range{{1, 0}, {1, 2}}));
  CHECK(key[0].at("textEdit").at("newText") == "template: ");
}

TEST_CASE("symbols and folding of a script that does not parse come from its text") {
  Editor editor;
  editor.type(withLine("  - THIRD:\n      template: LogState\n      transitions: {done: \n"));
  Json symbols = editor.symbols();
  REQUIRE(symbols.size() == 1);
  const Json& states = symbols[0].at("children");
  REQUIRE(states.size() == 3);
  CHECK(states[2].at("name") == "THIRD");
  CHECK(states[2].at("range") == toJson(Range{{13, 4}, {15, 24}}));
  Json folds = editor.folds();
  CHECK(folds.back() == Json{{"startLine", 13}, {"endLine", 15}});
}

TEST_CASE("no text makes the handlers fail: every cut of the scripts, nested brackets") {
  namespace fs = std::filesystem;
  Editor editor;
  std::vector<std::string> texts = {
      kScript,           std::string(5000, '['), std::string(5000, '{'), "- - - - - - - - - -",
      "a: [b: {c: d, e", "\"unclosed\n'x: y",    "\t\tname: x\n\t- y",   "---\n...\n---\n"};
  std::string deep;
  for (int i = 0; i < 300; ++i) deep += std::string(static_cast<size_t>(i), ' ') + "k:\n";
  texts.push_back(deep);
  std::ifstream in(fs::path(SMACHAC_SOURCE_DIR) / "examples/core/shorthand.yml");
  std::stringstream shorthand;
  shorthand << in.rdbuf();
  texts.push_back(shorthand.str());
  for (const std::string& text : texts) {
    for (size_t cut = 0; cut <= text.size(); cut += std::max<size_t>(1, text.size() / 23)) {
      std::string part = text.substr(0, cut);
      editor.type(part);
      LineIndex lines(part);
      CHECK_NOTHROW(editor.complete(lines.positionOf(part.size())));
      CHECK_NOTHROW(editor.complete(lines.positionOf(part.size() / 2)));
      CHECK_NOTHROW(editor.symbols());
      CHECK_NOTHROW(editor.folds());
    }
    size_t step = std::max<size_t>(1, text.size() / 200);
    for (size_t offset = 0; offset <= text.size(); offset += step) yamlContextAt(text, offset);
  }
}

}  // namespace smachac::lsp
