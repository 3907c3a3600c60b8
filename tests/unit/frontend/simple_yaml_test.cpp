// The simple YAML reader against yaml-cpp: on every script of the repository and on edge
// cases, it either gives up or builds exactly yaml-cpp's tree (values, kinds, locations).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "tests/unit/frontend/yaml_reader_diff.h"

using smachac::test::compareYamlReaders;
using smachac::test::YamlReaderComparison;

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> repositoryScripts() {
  std::vector<fs::path> files;
  for (const char* dir : {"tests/golden", "examples"}) {
    for (const auto& e : fs::recursive_directory_iterator(fs::path(SMACHAC_SOURCE_DIR) / dir)) {
      if (e.is_regular_file() && e.path().extension() == ".yml") files.push_back(e.path());
    }
  }
  return files;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void checkSame(const YamlReaderComparison& r) {
  if (!r.simple_read) return;
  CHECK(r.reference_clean);
  CHECK(r.simple == r.reference);
}

void checkRead(const char* text) {
  INFO(text);
  YamlReaderComparison r = compareYamlReaders(text);
  CHECK(r.simple_read);
  checkSame(r);
}

void checkGivesUp(const char* text) {
  INFO(text);
  CHECK_FALSE(compareYamlReaders(text).simple_read);
}

}  // namespace

TEST_CASE("every script of the repository reads as yaml-cpp reads it") {
  size_t read = 0, clean = 0;
  for (const fs::path& file : repositoryScripts()) {
    INFO(file.string());
    YamlReaderComparison r = compareYamlReaders(readFile(file));
    checkSame(r);
    read += r.simple_read;
    clean += r.reference_clean;
  }
  INFO("read " << read << " of " << clean << " clean scripts");
  CHECK(read * 10 >= clean * 7);  // the reader must handle the usual script, not only trivia
}

TEST_CASE("the core examples are read by the simple reader") {
  for (const char* name : {"sequence", "nesting", "concurrence", "sub_scripts", "sub/greet"}) {
    INFO(name);
    fs::path path = fs::path(SMACHAC_SOURCE_DIR) / "examples/core" / (std::string(name) + ".yml");
    YamlReaderComparison r = compareYamlReaders(readFile(path));
    CHECK(r.simple_read);
    checkSame(r);
  }
}

TEST_CASE("locations of keys, values and implicit nulls") {
  YamlReaderComparison r = compareYamlReaders("a:\nb: 'x'\nc: [1, {d: }]\n");
  REQUIRE(r.simple_read);
  CHECK(r.simple ==
        "1:1+1 map\n"
        "  key 1:1+1 \"a\"\n"
        "    1:1+1 null null\n"
        "  key 2:1+1 \"b\"\n"
        "    2:4+3 string \"x\"\n"
        "  key 3:1+1 \"c\"\n"
        "    3:4+1 list\n"
        "      3:5+1 int 1\n"
        "      3:8+1 map\n"
        "        key 3:9+1 \"d\"\n"
        "          3:12+1 null null\n");
  checkSame(r);
}

TEST_CASE("scalars") {
  checkRead("a: \"tab\\tquote\\\" backslash\\\\ slash\\/ nl\\n cr\\r\"\nb: 'it''s'\n");
  checkRead("a: \"# not a comment\"\nb: 'x: y'\nc: \"x, [y]\"\n");
  checkRead("a: b # comment\nc: x#y\nd: http://h:8/p\ne: a,b[c]{d}\n");
  checkRead("a: ~\nb: null\nc: NULL\nd: Null\n~: 1\n");
  checkRead("a: -1\nb: .5\nc: 0x1F\nd: 1e3\ne: true\nf: yes\ng: +.inf\nh: 0o17\n");
  checkRead("key with spaces  : v\n\"quoted key\": 1\n'single': 2\n");
  checkRead("a: 1   \nb: x y   \nc: 'q'   \n");
  checkRead("a: \xC3\xA9t\xC3\xA9\nb: '\xC3\xBC'\n\xC3\xA4: 1\n");
  checkRead("a: 1\nb: 2");
  checkRead("a: '`lambda ud: 1`'\n");
}

TEST_CASE("block structure") {
  checkRead("a:\nb: 1\nc:\n\nd:\n  # comment\n");
  checkRead("a:\n  b: 1\n  c:\n    - x\n    -   y\n");
  checkRead("s:\n  - a: 1\n    b: 2\n  - c: 3\n  -\n    d: 4\n");
  checkRead("s:\n- x\n- y\nt:\n- k: 1\n  j: 2\nu: 1\n");
  checkRead("a:\n    # deeper comment\n  b: 1\n");
  checkRead("# c\n\n---  # c\na: 1\n");
  checkRead("---\na: 1\n");
  checkRead("- A:\n    s: [x]\n- B: {}\n");
  checkRead("states:\n  - A:\n      template: X\n      # comment\n      outcomes: [o]\n");
}

TEST_CASE("flow collections") {
  checkRead("f: [a, 'b', \"c\", [d], {e: f}]\ng: {a: 1, b: , c: [x]}\n");
  checkRead("a: {}\nb: []\nc: { }\nd: [ ]\n");
  checkRead("a: [x y, z ,w]\nb: {k: [[l]], m: {n: o}}\n");
}

TEST_CASE("flow collections over several lines") {
  checkRead("a: [x,\n  y]\n");
  checkRead(
      "s:\n  - A: {t: X,\n         p: {n: 1, o: [a,\n\n               b]},\n     r: ,\n      z: "
      "}\n");
  checkRead("a: {\n  b: 1}\nc: [\n d]\n");
  checkRead("- {a: 1,\n   b: 2}\n- [x,   \n y]\n");
}

TEST_CASE("what the reader leaves to yaml-cpp") {
  checkGivesUp("a: 1\r\nb: 2\r\n");
  checkGivesUp(
      "\xEF\xBB\xBF"
      "a: 1\n");
  checkGivesUp("a:\tb\n");
  checkGivesUp("a:");
  checkGivesUp("a: &x 1\nb: *x\n");
  checkGivesUp("a: !str 3\n");
  checkGivesUp("a: |\n  x\n");
  checkGivesUp("a: >\n  x\n");
  checkGivesUp("a: foo\n  bar\n");
  checkGivesUp("a: x\n    # a deeper comment continues a plain scalar\nb: 1\n");
  checkGivesUp("a: 'x\n  y'\n");
  checkGivesUp("a: [x\n  , y]\n");
  checkGivesUp("a: [x, # comment\n  y]\n");
  checkGivesUp("a: [x,\n  # comment\n  y]\n");
  checkGivesUp("a:\n  b: [x,\n  y]\n");
  checkGivesUp("a: [x,\ny]\n");
  checkGivesUp("a: {b:\n  c}\n");
  checkGivesUp("a: [x, ]\n");
  checkGivesUp("a: [k: v]\n");
  checkGivesUp("a: 1\na: 2\n");
  checkGivesUp("a: 99999999999999999999\n");
  checkGivesUp("  a: 1\n");
  checkGivesUp("a: b: c\n");
  checkGivesUp("a: `x`\n");
  checkGivesUp("? a\n: 1\n");
  checkGivesUp("a: 1\n---\nb: 2\n");
  checkGivesUp("a: 1\n...\n");
  checkGivesUp("%YAML 1.2\n---\na: 1\n");
  checkGivesUp("s:\n  -\n  - x\n");
  checkGivesUp("s:\n  - - x\n");
  checkGivesUp("a: \"\\x41\"\n");
  checkGivesUp("a:\n  plain on its own line\n");
  checkGivesUp("");
  checkGivesUp("# only a comment\n");
}
