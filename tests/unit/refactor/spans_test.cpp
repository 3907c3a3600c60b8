// Spans of YAML nodes and mapping edits, on text parsed by the frontend's loader.
#include <doctest/doctest.h>

#include "frontend/yaml_loader.h"
#include "refactor/map_edits.h"
#include "refactor/yaml_spans.h"

namespace smachac::refactor {
namespace {

struct Parsed {
  SourceManager sources;
  DiagnosticEmitter diags;
  ir::Value root;
  SourceText text;

  explicit Parsed(const std::string& yaml) : text(yaml) {
    uint32_t file = sources.addFile("t.yml", yaml);
    std::optional<ir::Value> value = frontend::parseYaml(file, sources, diags);
    REQUIRE(value.has_value());
    root = std::move(*value);
  }

  const ir::MapEntry& entry(std::string_view key) const {
    for (const ir::MapEntry& e : root.asMap()) {
      if (e.key == key) return e;
    }
    FAIL("no key " << key);
    return root.asMap().front();
  }

  std::string valueText(std::string_view key) const {
    Span span = entryValueSpan(text, root, entry(key));
    return std::string(text.text().substr(span.begin, span.end - span.begin));
  }
};

}  // namespace

TEST_CASE("value spans in block context") {
  Parsed p(
      "plain: hello world   # comment\n"
      "quoted: 'it''s # not a comment'\n"
      "flow: {a: [1, '}'], b: \"x\"}  # c\n"
      "multi: {a: 1,\n"
      "  b: 2}\n"
      "block:\n"
      "  k: v\n"
      "  # inside\n"
      "  l:\n"
      "  - x\n"
      "seq:\n"
      "- 1\n"
      "- 2\n"
      "empty:\n"
      "scalar: |\n"
      "  text\n"
      "\n"
      "  more\n"
      "last: !str 5\n");
  CHECK(p.valueText("plain") == "hello world");
  CHECK(p.valueText("quoted") == "'it''s # not a comment'");
  CHECK(p.valueText("flow") == "{a: [1, '}'], b: \"x\"}");
  CHECK(p.valueText("multi") == "{a: 1,\n  b: 2}");
  CHECK(p.valueText("block") == "k: v\n  # inside\n  l:\n  - x");
  CHECK(p.valueText("seq") == "- 1\n- 2");
  CHECK(p.valueText("empty").empty());
  CHECK(p.valueText("scalar") == "|\n  text\n\n  more");
  CHECK(p.valueText("last") == "5");
}

TEST_CASE("value spans in flow context") {
  Parsed p("m: {a: x y, b: [p, q], c: 'z', d: e}\n");
  const ir::Value& m = p.entry("m").value;
  auto text = [&](size_t i) {
    Span s = entryValueSpan(p.text, m, m.asMap()[i]);
    return std::string(p.text.text().substr(s.begin, s.end - s.begin));
  };
  CHECK(text(0) == "x y");
  CHECK(text(1) == "[p, q]");
  CHECK(text(2) == "'z'");
  CHECK(text(3) == "e");
}

TEST_CASE("entryLines take the comment lines above an entry") {
  Parsed p("a: 1\n# about b\n# more\nb:\n  - x\n\nc: 3\n");
  Span lines = entryLines(p.text, p.root, p.entry("b"));
  CHECK(p.text.text().substr(lines.begin, lines.end - lines.begin) ==
        "# about b\n# more\nb:\n  - x\n");
}

TEST_CASE("MapEditor deletes runs of flow entries with one comma") {
  Parsed p("m: {a: 1, b: 2, c: 3, d: 4}\n");
  const ir::Value& m = p.entry("m").value;
  auto deleted = [&](std::vector<size_t> indices) {
    EditList edits;
    MapEditor(p.text, edits).deleteEntries(m, indices);
    return edits.render(p.text.text(), {0, p.text.size()});
  };
  CHECK(deleted({0}) == "m: {b: 2, c: 3, d: 4}\n");
  CHECK(deleted({1, 2}) == "m: {a: 1, d: 4}\n");
  CHECK(deleted({2, 3}) == "m: {a: 1, b: 2}\n");
  CHECK(deleted({0, 3}) == "m: {b: 2, c: 3}\n");
  CHECK(deleted({0, 1, 2, 3}) == "m: {}\n");
}

TEST_CASE("MapEditor adds entries in the mapping's style") {
  Parsed p("top:\n  a: 1\n  b: [x]\nflow: {a: 1}\nempty: {}\n");
  EditList edits;
  MapEditor maps(p.text, edits);
  maps.append(p.entry("top").value, "c", "3");
  maps.insertBefore(p.entry("top").value, 0, "z", "0");
  maps.append(p.entry("flow").value, "b", "2");
  maps.append(p.entry("empty").value, "k", "v");
  maps.insertAfter(p.root, 0, "after", "top");
  CHECK(edits.render(p.text.text(), {0, p.text.size()}) ==
        "top:\n  z: 0\n  a: 1\n  b: [x]\n  c: 3\nafter: top\nflow: {a: 1, b: 2}\nempty: {k: v}\n");
}

TEST_CASE("MapEditor deletes block entries with their comments; a last line without break") {
  Parsed p("a: 1\n# b's\nb: 2\nc: 3");
  EditList edits;
  MapEditor maps(p.text, edits);
  maps.deleteEntry(p.root, 1);
  maps.append(p.root, "d", "4");
  CHECK(edits.render(p.text.text(), {0, p.text.size()}) == "a: 1\nc: 3\nd: 4");
}

}  // namespace smachac::refactor
