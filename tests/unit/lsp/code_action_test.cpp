// Code actions and the text edits they carry: the minimal diff of two texts, WorkspaceEdit
// JSON, and every action applied to its script, compared with the script it must give.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "frontend/lower.h"
#include "lsp/features/features.h"
#include "lsp/uri.h"
#include "lsp/workspace.h"
#include "lsp/workspace_edit.h"

namespace smachac::lsp {
namespace {

/// Applies LSP text edits (ranges in `text`, not overlapping) as a client does.
std::string applyEdits(const std::string& text, const Json& edits) {
  LineIndex lines(text);
  std::vector<std::tuple<size_t, size_t, std::string>> splices;
  for (const Json& edit : edits) {
    splices.emplace_back(lines.offsetOf(positionFromJson(edit["range"]["start"])),
                         lines.offsetOf(positionFromJson(edit["range"]["end"])),
                         edit["newText"].get<std::string>());
  }
  std::sort(splices.begin(), splices.end());
  for (size_t i = 1; i < splices.size(); ++i) {
    REQUIRE(std::get<1>(splices[i - 1]) <= std::get<0>(splices[i]));
  }
  std::string out = text;
  for (auto it = splices.rbegin(); it != splices.rend(); ++it) {
    auto [begin, end, replacement] = *it;
    out.replace(begin, end - begin, replacement);
  }
  return out;
}

std::string applyEdits(const std::string& text, const std::vector<TextEdit>& edits) {
  Json json = Json::array();
  for (const TextEdit& edit : edits) json.push_back(toJson(edit));
  return applyEdits(text, json);
}

using Files = std::map<std::string, std::string>;  ///< URI -> text

/// Applies a WorkspaceEdit to `files`: created files start empty; a versioned edit must be
/// for the version `versions` gives.
Files applyWorkspaceEdit(Files files, const Json& edit,
                         const std::map<std::string, int>& versions) {
  if (edit.contains("changes")) {
    for (const auto& [uri, edits] : edit["changes"].items()) {
      files[uri] = applyEdits(files[uri], edits);
    }
    return files;
  }
  for (const Json& change : edit.at("documentChanges")) {
    if (change.contains("kind")) {
      REQUIRE(change["kind"] == "create");
      REQUIRE(!files.contains(change["uri"].get<std::string>()));
      files[change["uri"].get<std::string>()] = "";
      continue;
    }
    std::string uri = change["textDocument"]["uri"].get<std::string>();
    const Json& version = change["textDocument"]["version"];
    if (!version.is_null()) CHECK(version.get<int>() == versions.at(uri));
    files[uri] = applyEdits(files.at(uri), change["edits"]);
  }
  return files;
}

std::string readScript(const std::string& name) {
  std::ifstream in(std::string(SMACHAC_SOURCE_DIR) + "/tests/lsp/sessions/scripts/" + name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// `text` with its one occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  REQUIRE(text.find(from, at + 1) == std::string::npos);
  return text.replace(at, from.size(), to);
}

const Json kRichClient = Json::parse(R"({
  "textDocument": {"codeAction": {"codeActionLiteralSupport": {}}},
  "workspace": {"workspaceEdit": {"documentChanges": true, "resourceOperations": ["create"]}}
})");

/// One open script and the code actions at a place in it.
class Editor {
 public:
  Editor(const std::string& script, Json capabilities = kRichClient)
      : workspace_({}),
        uri_(
            uriFromPath(std::string(SMACHAC_SOURCE_DIR) + "/tests/lsp/sessions/scripts/" + script)),
        text_(readScript(script)) {
    workspace_.setClientCapabilities(std::move(capabilities));
    workspace_.documents().open(uri_, text_, 7);
    workspace_.opened(uri_);
  }

  const std::string& uri() const { return uri_; }
  const std::string& text() const { return text_; }

  Json actions(Position start, Position end, Json only = nullptr) {
    Json context = {{"diagnostics", Json::array()}};
    if (!only.is_null()) context["only"] = std::move(only);
    Json params = {{"textDocument", {{"uri", uri_}}},
                   {"range", {{"start", toJson(start)}, {"end", toJson(end)}}},
                   {"context", context}};
    return codeAction(workspace_, params);
  }
  Json actions(Position at) { return actions(at, at); }

  /// The action titled `title` among those at `start`-`end`.
  Json action(const std::string& title, Position start, Position end) {
    Json all = actions(start, end);
    for (const Json& action : all) {
      if (action["title"] == title) return action;
    }
    FAIL("no action `" << title << "` in " << all.dump(2));
    return nullptr;
  }
  Json action(const std::string& title, Position at) { return action(title, at, at); }

  /// The document's text after the action's edit.
  std::string applied(const Json& action) {
    Files files = applyWorkspaceEdit({{uri_, text_}}, action["edit"], {{uri_, 7}});
    return files.at(uri_);
  }

 private:
  Workspace workspace_;
  std::string uri_;
  std::string text_;
};

std::vector<std::string> titles(const Json& actions) {
  std::vector<std::string> out;
  for (const Json& action : actions) out.push_back(action["title"].get<std::string>());
  return out;
}

/// Whether `text` lowers without errors (as the document's sibling, for its sub-scripts).
bool lowers(const std::string& text) {
  SourceManager sources;
  DiagnosticEmitter diags;
  std::string path = std::string(SMACHAC_SOURCE_DIR) + "/tests/lsp/sessions/scripts/x.yml";
  return frontend::lowerScriptText(path, text, {}, sources, diags).has_value() &&
         !diags.hasErrors();
}

}  // namespace

TEST_CASE("diffEdits: nothing for equal texts; a change is narrowed to the bytes that differ") {
  CHECK(diffEdits("a: 1\nb: 2\n", "a: 1\nb: 2\n").empty());
  std::vector<TextEdit> edits = diffEdits("a: [x]\nb: 2\n", "a: [x, y]\nb: 2\n");
  REQUIRE(edits.size() == 1);
  CHECK(edits[0] == TextEdit{{{0, 5}, {0, 5}}, ", y"});
  edits = diffEdits("a\nb\nc\n", "a\nnew\nb\nc\n");
  REQUIRE(edits.size() == 1);
  CHECK(edits[0] == TextEdit{{{1, 0}, {1, 0}}, "new\n"});
  edits = diffEdits("x\n", "");
  REQUIRE(edits.size() == 1);
  CHECK(edits[0] == TextEdit{{{0, 0}, {1, 0}}, ""});
}

TEST_CASE("diffEdits: distant changes are separate edits; unchanged lines are not touched") {
  std::string before = "one\ntwo\nthree\nfour\nfive\nsix\n";
  std::string after = "one\nTWO\nthree\nfour\nfive\nsix\nseven\n";
  std::vector<TextEdit> edits = diffEdits(before, after);
  REQUIRE(edits.size() == 2);
  CHECK(edits[0] == TextEdit{{{1, 0}, {1, 3}}, "TWO"});
  CHECK(edits[1] == TextEdit{{{6, 0}, {6, 0}}, "seven\n"});
  CHECK(applyEdits(before, edits) == after);
}

TEST_CASE("diffEdits never splits a UTF-8 sequence or a CRLF; positions count UTF-16 units") {
  // `é` and `è` share their first byte: the edit replaces the whole character.
  std::vector<TextEdit> edits = diffEdits("😀é\r\n", "😀è\r\n");
  REQUIRE(edits.size() == 1);
  CHECK(edits[0] == TextEdit{{{0, 2}, {0, 3}}, "è"});
  // A line break changed from LF to CRLF: the edit does not end between `\r` and `\n`.
  edits = diffEdits("a\r\nb\n", "a\r\nb\r\n");
  CHECK(applyEdits("a\r\nb\n", edits) == "a\r\nb\r\n");
  edits = diffEdits("a\rb\r\n", "a\r\n");
  CHECK(applyEdits("a\rb\r\n", edits) == "a\r\n");
}

TEST_CASE("diffEdits gives edits that turn any text into any other") {
  std::mt19937 random(7);
  const std::vector<std::string> pieces = {"a", "b", "\n", "\r\n", "\r", "é", "😀", ": ", "  "};
  auto draw = [&](size_t count) {
    std::vector<std::string> out;
    for (size_t i = 0; i < count; ++i) out.push_back(pieces[random() % pieces.size()]);
    return out;
  };
  auto join = [](const std::vector<std::string>& parts) {
    std::string out;
    for (const std::string& part : parts) out += part;
    return out;
  };
  for (int round = 0; round < 500; ++round) {
    std::vector<std::string> before = draw(random() % 40);
    std::vector<std::string> after = before;
    for (int k = random() % 4; k >= 0; --k) {
      size_t at = after.empty() ? 0 : random() % after.size();
      size_t erase = std::min<size_t>(random() % 4, after.size() - at);
      after.erase(after.begin() + at, after.begin() + at + erase);
      std::vector<std::string> inserted = draw(random() % 4);
      after.insert(after.begin() + at, inserted.begin(), inserted.end());
    }
    INFO("before: " << Json(join(before)).dump() << " after: " << Json(join(after)).dump());
    CHECK(applyEdits(join(before), diffEdits(join(before), join(after))) == join(after));
  }
}

TEST_CASE("diffEdits of texts too different for the line diff is one edit, still exact") {
  std::string before;
  std::string after;
  for (int i = 0; i < 3000; ++i) {
    before += "line " + std::to_string(i) + "\n";
    after += "LINE " + std::to_string(i) + "\n";
  }
  std::vector<TextEdit> edits =
      diffEdits("head\n" + before + "tail\n", "head\n" + after + "tail\n");
  CHECK(edits.size() == 1);
  CHECK(applyEdits("head\n" + before + "tail\n", edits) == "head\n" + after + "tail\n");
}

TEST_CASE("a WorkspaceEdit uses documentChanges when the client has them, else changes") {
  std::vector<TextEdit> edits = {{{{0, 1}, {0, 2}}, "x"}};
  WorkspaceEdit plain(editSupport(Json::object()));
  CHECK(!plain.canCreateFiles());
  plain.editDocument("file:///a.yml", 3, edits);
  plain.editDocument("file:///a.yml", 3, {{{{1, 0}, {1, 0}}, "y"}});
  CHECK(plain.toJson() == Json::parse(R"({"changes": {"file:///a.yml": [
    {"range": {"start": {"line": 0, "character": 1}, "end": {"line": 0, "character": 2}},
     "newText": "x"},
    {"range": {"start": {"line": 1, "character": 0}, "end": {"line": 1, "character": 0}},
     "newText": "y"}]}})"));
  EditSupport support = editSupport(kRichClient);
  CHECK(support.document_changes);
  CHECK(support.create_files);
  WorkspaceEdit rich(support);
  rich.createFile("file:///b.yml");
  rich.editDocument("file:///b.yml", std::nullopt, edits);
  rich.editDocument("file:///a.yml", 3, edits);
  Json edit_json = toJson(edits[0]);
  CHECK(rich.toJson() == Json{{"documentChanges",
                               {{{"kind", "create"}, {"uri", "file:///b.yml"}},
                                {{"textDocument", {{"uri", "file:///b.yml"}, {"version", nullptr}}},
                                 {"edits", {edit_json}}},
                                {{"textDocument", {{"uri", "file:///a.yml"}, {"version", 3}}},
                                 {"edits", {edit_json}}}}}});
  Json no_create = Json::parse(R"({"workspace": {"workspaceEdit": {"documentChanges": true}}})");
  CHECK(!WorkspaceEdit(editSupport(no_create)).canCreateFiles());
  CHECK(!editSupport(Json::parse(R"({"workspace": {"workspaceEdit": 5}})")).document_changes);
  CHECK(!editSupport(nullptr).document_changes);
}

TEST_CASE("a fix-it goes to the diagnostic emitted last, unless that one was silenced") {
  WarningOptions options;
  REQUIRE(!options.apply("-Wno-unknown-root-key"));
  DiagnosticEmitter diags(options);
  diags.emit<DiagKind::UnknownTransitionTarget>(SourceLoc{1, 2, 3, 4}, "B", "root", "");
  diags.fixIt(std::string("A"));
  diags.fixIt(std::nullopt);  // no match: the fix-it stays
  diags.emit<DiagKind::UnknownRootKey>(SourceLoc{1, 5, 1, 4}, "stats", "");
  diags.fixIt(std::string("states"));
  REQUIRE(diags.diagnostics().size() == 1);
  CHECK(diags.diagnostics()[0].fix == "A");
}

TEST_CASE("quick fix: a \"did you mean\" replaces the name, in the quotes it was written in") {
  Editor editor("fix_names.yml");
  const std::string& text = editor.text();
  CHECK(editor.applied(editor.action("Change `outcome` to `outcomes`", {5, 3})) ==
        replaced(text, "outcome: [done]\nuserdata", "outcomes: [done]\nuserdata"));
  CHECK(editor.applied(editor.action("Change `COUNTT` to `COUNT`", {10, 33})) ==
        replaced(text, "succeeded: COUNTT", "succeeded: COUNT"));
  CHECK(editor.applied(
            editor.action("Change `PrintUserdataStat` to `PrintUserdataState`", {9, 20})) ==
        replaced(text, "PrintUserdataStat\n", "PrintUserdataState\n"));
  Json action = editor.action("Change `cont` to `count`", {15, 33});
  CHECK(action["kind"] == "quickfix");
  CHECK(action["isPreferred"] == true);
  CHECK(action["diagnostics"][0]["code"] == "expr-unknown-name");
  CHECK(editor.applied(action) == replaced(text, "'cont + 1'", "'count + 1'"));
}

TEST_CASE("quick fix: an outcome without transition gets one, or becomes the container's") {
  Editor editor("fix_outcomes.yml");
  const std::string& text = editor.text();
  CHECK(titles(editor.actions({9, 26})) ==
        std::vector<std::string>{"Add transition `tails: WORK` to `FLIP`",
                                 "Add transition `tails: done` to `FLIP`",
                                 "Add outcome `tails` to `fix_outcomes`"});
  CHECK(editor.applied(editor.action("Add transition `tails: WORK` to `FLIP`", {9, 26})) ==
        replaced(text, "{heads: WORK}", "{heads: WORK, tails: WORK}"));
  CHECK(editor.applied(editor.action("Add outcome `tails` to `fix_outcomes`", {9, 26})) ==
        replaced(text, "outcomes: [done]", "outcomes: [done, tails]"));
  // The last state has no transitions at all: the key is added in the mapping's style.
  CHECK(editor.applied(editor.action("Add transition `yes: done` to `LAST`", {23, 18})) ==
        text + "      transitions: {yes: done}\n");
}

TEST_CASE("quick fix: unknown targets and undeclared outcomes become declared outcomes") {
  Editor editor("fix_outcomes.yml");
  const std::string& text = editor.text();
  CHECK(editor.applied(editor.action("Add outcome `give_up` to `WORK`", {20, 50})) ==
        replaced(text, "        - finished\n", "        - finished\n        - give_up\n"));
  CHECK(editor.applied(editor.action("Add outcome `given_up` to `WORK`", {15, 40})) ==
        replaced(text, "        - finished\n", "        - finished\n        - given_up\n"));
}

TEST_CASE("quick fix: userdata a state reads becomes an input key") {
  Editor editor("fix_keys.yml");
  const std::string& text = editor.text();
  CHECK(editor.applied(editor.action("Add `step` to the input_keys of `ADD`", {12, 41})) ==
        replaced(text, "        - count\n", "        - count\n        - step\n"));
  CHECK(editor.applied(editor.action("Add `count` to the input_keys of `SHOW`", {22, 26})) ==
        text + "      input_keys: [count]\n");
}

TEST_CASE("contain: the selected root states move into a new container") {
  Editor editor("fix_refactor.yml");
  Json action = editor.action("Contain `HELLO` to `FLIP` in a new StateMachine", {8, 4}, {13, 6});
  CHECK(action["kind"] == "refactor.rewrite");
  CHECK(editor.applied(action) ==
        replaced(editor.text(),
                 "  # say hello first\n  - HELLO:\n      template: PrintUserdataState\n"
                 "      input_keys: [greeting]\n      transitions: {succeeded: FLIP}  # then flip "
                 "a coin\n  - FLIP:\n      template: RandomOutcomeState\n      outcomes: [heads, "
                 "tails]\n      transitions: {heads: BYE, tails: HELLO}\n",
                 "  - CONTAINER:\n      template: StateMachine\n      input_keys: [greeting]\n"
                 "      outcomes: [container_outcome_1]\n"
                 "      transitions: {container_outcome_1: BYE}\n      states:\n"
                 "        # say hello first\n        - HELLO:\n"
                 "            template: PrintUserdataState\n            input_keys: [greeting]\n"
                 "            transitions: {succeeded: FLIP}  # then flip a coin\n"
                 "        - FLIP:\n            template: RandomOutcomeState\n"
                 "            outcomes: [heads, tails]\n"
                 "            transitions: {heads: container_outcome_1, tails: HELLO}\n"));
  Json concurrence =
      editor.action("Contain `HELLO` to `FLIP` in a new Concurrence", {8, 4}, {13, 6});
  CHECK(lowers(editor.applied(concurrence)));
  CHECK(editor.actions({8, 4}, {13, 6}, Json::array({"quickfix"})).empty());
  CHECK(titles(editor.actions({16, 4}, {16, 6}, Json::array({"refactor.rewrite"}))) ==
        std::vector<std::string>{"Contain `BYE` in a new StateMachine",
                                 "Contain `BYE` in a new Concurrence"});
}

TEST_CASE("extract: a root state becomes a new sub-script next to the document") {
  Editor editor("fix_refactor.yml");
  Json action = editor.action("Extract `HELLO` into sub-script `hello.yml`", {8, 6});
  CHECK(action["kind"] == "refactor.extract");
  std::string sub_uri =
      uriFromPath(std::string(SMACHAC_SOURCE_DIR) + "/tests/lsp/sessions/scripts/hello.yml");
  Files files =
      applyWorkspaceEdit({{editor.uri(), editor.text()}}, action["edit"], {{editor.uri(), 7}});
  CHECK(files.at(sub_uri) ==
        "- HELLO:\n    template: PrintUserdataState\n    input_keys: [greeting]\n");
  CHECK(files.at(editor.uri()) ==
        replaced(editor.text(),
                 "      template: PrintUserdataState\n      input_keys: [greeting]\n"
                 "      transitions: {succeeded: FLIP}",
                 "      script: hello\n      transitions: {succeeded: FLIP}"));
  // Only on a root state's name, and only for a client that can create the file.
  CHECK(editor.actions({9, 8}).empty());
  Editor plain("fix_refactor.yml", Json::parse(R"({"textDocument": {"codeAction":
      {"codeActionLiteralSupport": {}}}})"));
  CHECK(plain.actions({8, 6}).empty());
}

TEST_CASE("no code actions without literal support, off the text, or for a closed document") {
  Editor editor("fix_outcomes.yml", Json::object());
  CHECK(editor.actions({9, 26}) == Json::array());
  Editor rich("fix_outcomes.yml");
  CHECK(rich.actions({400, 0}, {500, 3}) == Json::array());
  Workspace workspace({});
  Json params = {{"textDocument", {{"uri", "file:///nowhere.yml"}}},
                 {"range", {{"start", toJson(Position{})}, {"end", toJson(Position{})}}},
                 {"context", {{"diagnostics", Json::array()}}}};
  CHECK(codeAction(workspace, params) == Json::array());
}

TEST_CASE("fixes in the `changes` form for a client without documentChanges") {
  Editor editor("fix_outcomes.yml", Json::parse(R"({"textDocument": {"codeAction":
      {"codeActionLiteralSupport": {}}}})"));
  Json action = editor.action("Add outcome `tails` to `fix_outcomes`", {9, 26});
  CHECK(action["edit"].contains("changes"));
  CHECK(editor.applied(action) ==
        replaced(editor.text(), "outcomes: [done]", "outcomes: [done, tails]"));
}

}  // namespace smachac::lsp
