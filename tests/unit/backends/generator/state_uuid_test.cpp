// State ids: UUID4-shaped, deterministic, independent of the script's directory.
#include "backends/generator/state_uuid.h"

#include <doctest/doctest.h>

#include <regex>

namespace smachac::generator {
namespace {

TEST_CASE("ids match SMACHA's UUID4 pattern") {
  std::regex uuid4("[a-f0-9]{8}[a-f0-9]{4}4[a-f0-9]{3}[89ab][a-f0-9]{3}[a-f0-9]{12}");
  for (const char* path : {"ROOT", "ROOT/A", "ROOT/SUB/B", "x", ""}) {
    std::string id = stateUuid("script.yml", path);
    CHECK(id.size() == 32);
    CHECK(std::regex_match(id, uuid4));
  }
}

TEST_CASE("ids are deterministic and depend on the file name and the state path only") {
  CHECK(stateUuid("a.yml", "ROOT/X") == stateUuid("a.yml", "ROOT/X"));
  CHECK(stateUuid("a.yml", "ROOT/X") == stateUuid("/some/dir/a.yml", "ROOT/X"));
  CHECK(stateUuid("a.yml", "ROOT/X") == stateUuid("other/a.yml", "ROOT/X"));
  CHECK(stateUuid("a.yml", "ROOT/X") != stateUuid("b.yml", "ROOT/X"));
  CHECK(stateUuid("a.yml", "ROOT/X") != stateUuid("a.yml", "ROOT/Y"));
  CHECK(stateUuid("ab", "c") != stateUuid("a", "bc"));
}

}  // namespace
}  // namespace smachac::generator
