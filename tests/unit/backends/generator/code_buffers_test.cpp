// CodeBuffers: insertion orders, keyed buffers, SMACHA's joining and stripping.
#include "backends/generator/code_buffers.h"

#include <doctest/doctest.h>

namespace smachac::generator {
namespace {

size_t index(std::string_view name) { return *bufferIndex(name); }

TEST_CASE("the thirteen buffers in SMACHA's order, with their kinds") {
  REQUIRE(bufferSpecs().size() == 13);
  CHECK(bufferSpecs()[0].name == "base_header");
  CHECK(bufferSpecs()[12].name == "main");
  CHECK(bufferSpecs()[index("header")].kind == BufferKind::Keyed);
  CHECK(bufferSpecs()[index("header_userdata")].kind == BufferKind::Keyed);
  CHECK(bufferSpecs()[index("body")].kind == BufferKind::List);
  CHECK_FALSE(bufferIndex("meta").has_value());
}

TEST_CASE("later snippets go after earlier ones, except in footer, execute, base_footer, main") {
  CodeBuffers buffers;
  for (std::string_view name : {"body", "footer", "execute", "base_footer", "main"}) {
    buffers.insert(index(name), "first\n", "sm");
    buffers.insert(index(name), "second\n", "sm");
  }
  CHECK(buffers.joined(index("body")) == "first\n\nsecond\n\n");
  for (std::string_view name : {"footer", "execute", "base_footer", "main"}) {
    CHECK(buffers.joined(index(name)) == "second\n\nfirst\n\n");
  }
}

TEST_CASE("keyed buffers collect snippets by container, in first-insertion order") {
  CodeBuffers buffers;
  size_t ud = index("header_userdata");
  buffers.insert(ud, "sm_b.userdata.x = 1\n", "B");
  buffers.insert(ud, "sm.userdata.y = 2\n", "sm");
  buffers.insert(ud, "sm_b.userdata.z = 3\n", "B");
  auto entries = buffers.joinedEntries(ud);
  REQUIRE(entries.size() == 2);
  CHECK(entries[0].first == "B");
  CHECK(entries[0].second == "sm_b.userdata.x = 1\n\nsm_b.userdata.z = 3\n\n");
  tmpl::Value value = buffers.value(ud, /*strip=*/true);
  REQUIRE(value.isDict());
  CHECK(value.dict().findString("sm")->s() == "sm.userdata.y = 2");
}

TEST_CASE("buffer values for templates: joined, stripped for the base only") {
  CodeBuffers buffers;
  buffers.insert(index("imports"), "import os\n", "sm");
  CHECK(buffers.value(index("imports"), false).s() == "import os\n\n");
  CHECK(buffers.value(index("imports"), true).s() == "import os");
  CHECK(buffers.value(index("defs"), true).s().empty());
  CHECK(stripWhitespace(" \n\t x y \n") == "x y");
  CHECK(stripWhitespace(" \n ").empty());
}

TEST_CASE("taking a buffer gives the same value as reading it, and empties the buffer") {
  CodeBuffers buffers;
  for (std::string_view name : {"body", "main", "header"}) {
    buffers.insert(index(name), " first\n", "sm");
    buffers.insert(index(name), "second\n", "sm");
  }
  for (std::string_view name : {"body", "main"}) {
    std::string read = buffers.value(index(name), true).s();
    CHECK(buffers.take(index(name), true).s() == read);
    CHECK(buffers.joined(index(name)).empty());
  }
  CHECK(buffers.take(index("body"), false).s().empty());
  tmpl::Value header = buffers.take(index("header"), false);
  REQUIRE(header.isDict());
  CHECK(header.dict().findString("sm")->s() == " first\n\nsecond\n\n");
  CHECK(buffers.joinedEntries(index("header")).empty());
}

}  // namespace
}  // namespace smachac::generator
