// The protocol plumbing: framing, UTF-16 positions, file URIs and incremental changes.
#include <doctest/doctest.h>

#include <sstream>

#include "lsp/documents.h"
#include "lsp/json_rpc.h"
#include "lsp/positions.h"
#include "lsp/uri.h"
#include "lsp/workspace.h"

namespace smachac::lsp {

TEST_CASE("frames are read by Content-Length, whatever the header case and extra headers") {
  std::istringstream in(
      "Content-Length: 2\r\n\r\n{}content-length:3\r\nContent-Type: x\r\n\r\n[1]X-Other: "
      "1\r\n\r\n");
  Frame first = readFrame(in);
  CHECK(first.status == FrameStatus::Ok);
  CHECK(first.body == "{}");
  Frame second = readFrame(in);
  CHECK(second.status == FrameStatus::Ok);
  CHECK(second.body == "[1]");
  CHECK(readFrame(in).status == FrameStatus::BadHeader);
  CHECK(readFrame(in).status == FrameStatus::EndOfInput);
}

TEST_CASE("a truncated body is the end of input; a written frame reads back") {
  std::istringstream truncated("Content-Length: 10\r\n\r\n{}");
  CHECK(readFrame(truncated).status == FrameStatus::EndOfInput);
  std::ostringstream out;
  writeFrame(out, Json{{"a", "é"}});
  CHECK(out.str() == "Content-Length: 10\r\n\r\n{\"a\":\"é\"}");
  std::istringstream back(out.str());
  CHECK(Json::parse(readFrame(back).body)["a"] == "é");
}

TEST_CASE("positions count UTF-16 code units; SourceLoc columns count bytes") {
  std::string text = "a: é\nb: 😀x\r\nlast";
  LineIndex lines(text);
  CHECK(lines.lineCount() == 3);
  CHECK(lines.lineText(1) == "b: 😀x");
  CHECK(lines.positionOf(text.find('x')) == Position{1, 5});
  CHECK(lines.offsetOf(Position{1, 5}) == text.find('x'));
  CHECK(lines.offsetOf(Position{0, 99}) == text.find('\n'));  // clamped to the line
  CHECK(lines.offsetOf(Position{7, 0}) == text.size());
  Range range = lines.rangeOf(SourceLoc{1, 2, 4, 4});  // `😀` is 4 bytes at column 4
  CHECK(range == Range{{1, 3}, {1, 5}});
  CHECK(lines.rangeOf(SourceLoc{1, 0, 0, 1}) == Range{});
}

TEST_CASE("file URIs are percent-decoded; other schemes have no path") {
  CHECK(pathFromUri("file:///tmp/a%20b/c.yml") == "/tmp/a b/c.yml");
  CHECK(pathFromUri("file://localhost/x.yml") == "/x.yml");
  CHECK(!pathFromUri("untitled:Untitled-1"));
  CHECK(!pathFromUri("file:///bad%2"));
  CHECK(!pathFromUri("file:///nul%00"));
  CHECK(uriFromPath("/tmp/a b/ü.yml") == "file:///tmp/a%20b/%C3%BC.yml");
  CHECK(pathFromUri(uriFromPath("/tmp/a b/ü.yml")) == "/tmp/a b/ü.yml");
}

TEST_CASE("incremental changes apply in order; a reversed range changes nothing") {
  DocumentStore store;
  store.open("untitled:a", "name: x\nstates: []\n", 1);
  Json changes = Json::parse(R"([
    {"range": {"start": {"line": 0, "character": 6}, "end": {"line": 0, "character": 7}},
     "text": "yz"},
    {"range": {"start": {"line": 1, "character": 0}, "end": {"line": 1, "character": 0}},
     "text": "# c\n"}])");
  REQUIRE(store.change("untitled:a", 2, changes));
  CHECK(store.find("untitled:a")->text == "name: yz\n# c\nstates: []\n");
  CHECK(store.find("untitled:a")->version == 2);
  Json reversed = Json::parse(R"([{"range": {"start": {"line": 1, "character": 0},
    "end": {"line": 0, "character": 0}}, "text": ""}])");
  CHECK(!store.change("untitled:a", 3, reversed));
  CHECK(store.find("untitled:a")->version == 2);
  CHECK(store.overlay().empty());  // not a file
}

}  // namespace smachac::lsp

namespace smachac::lsp {

TEST_CASE("a workspace analyses a document again after each change") {
  Workspace workspace({});
  const std::string uri = "untitled:w.yml";
  workspace.documents().open(uri,
                             "name: w\ntemplate: Base\noutcomes: [done]\nuserdata: {text: hi}\n"
                             "states:\n  - A: {template: PrintUserdataState, input_keys: [text], "
                             "transitions: {succeeded: done}}\n",
                             1);
  workspace.opened(uri);
  CHECK(workspace.takeStale() == std::vector<std::string>{uri});
  CHECK(workspace.analysis(uri)->diagnostics.empty());
  Json change = Json::parse(R"([{"range": {"start": {"line": 5, "character": 59},
    "end": {"line": 5, "character": 60}}, "text": "u"}])");
  REQUIRE(workspace.documents().change(uri, 2, change));
  workspace.changed(uri);
  const Analysis* analysis = workspace.analysis(uri);
  REQUIRE(analysis->diagnostics.size() == 1);
  CHECK(analysis->version == 2);
  CHECK(workspace.analysis("untitled:other") == nullptr);
}

}  // namespace smachac::lsp
