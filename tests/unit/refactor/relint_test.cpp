// Every contain golden case (tests/golden/contain) run through the library: the result loads
// again, and lints without errors — and without warnings when the input had none, except the
// version-dependent-outcome-map warnings that a Concurrence made from a sequence may deserve.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/unit/refactor/scripts.h"

namespace smachac::refactor {
namespace {

namespace fs = std::filesystem;

struct GoldenCase {
  std::string path;
  ContainRequest request;
  std::vector<std::string> script_dirs;
};

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// The request of a case's `# ARGS: contain %s NAME TYPE STATE... [options]` line.
std::optional<GoldenCase> readCase(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> args = words(line);
  if (args.size() < 6 || args[1] != "ARGS:" || args[2] != "contain") return std::nullopt;
  GoldenCase c{path.string(), {args[4], ir::StateKind::StateMachine, {}, {}}, {}};
  if (args[5] == "Concurrence") c.request.kind = ir::StateKind::Concurrence;
  for (size_t i = 6; i < args.size(); ++i) {
    if (args[i] == "-o") {
      ++i;
    } else if (args[i] == "-S" && i + 1 < args.size()) {
      c.script_dirs.push_back((path.parent_path() / args[++i]).string());
    } else if (args[i] == "--default-target" && i + 1 < args.size()) {
      c.request.default_target = args[++i];
    } else {
      c.request.states.push_back(args[i]);
    }
  }
  return c;
}

/// The warnings of `result` that containing may not add. A Concurrence made from a sequence
/// maps outcomes of states that, once they run at the same time, can all end the way their
/// entries need; SMACH versions choose among such entries differently, and lint says so.
size_t warningsContainingMayNotAdd(const testing::LintResult& result) {
  auto version_dependent =
      std::count(result.kinds.begin(), result.kinds.end(), "version-dependent-outcome-map");
  return result.warnings - static_cast<size_t>(version_dependent);
}

}  // namespace

TEST_CASE("contain golden cases load and lint again") {
  fs::path dir = fs::path(SMACHAC_SOURCE_DIR) / "tests/golden/contain";
  size_t checked = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".yml" || name.starts_with("fail_")) continue;
    std::optional<GoldenCase> c = readCase(entry.path());
    if (!c) continue;
    CAPTURE(name);
    std::optional<std::string> out =
        testing::containFile(c->path, c->request, nullptr, c->script_dirs);
    if (!out) continue;  // a usage error case
    testing::LintResult before = testing::lint(c->path, c->script_dirs);
    testing::TempDir temp;
    c->script_dirs.insert(c->script_dirs.begin(), dir.string());  // the case's own folder
    testing::LintResult after = testing::lint(temp.write(name, *out), c->script_dirs);
    CAPTURE(after.kinds);
    CHECK(after.errors == 0);
    if (before.errors == 0 && before.warnings == 0) CHECK(warningsContainingMayNotAdd(after) == 0);
    ++checked;
  }
  CHECK(checked >= 10);
}

}  // namespace smachac::refactor
