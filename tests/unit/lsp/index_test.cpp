// The script index (lsp/script_index.h): userdata keys across container interfaces and
// remapping, the roles of writes, params resolved to the nearest entry, positions, documents
// that do not parse, sub-scripts; and what hover and definition read about templates
// (lsp/index_templates.h, backends/meta/template_help.h): cache copies, user templates, markdown.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "backends/meta/template_help.h"
#include "backends/tmpl/values/value_convert.h"
#include "ir/support/version.h"
#include "lsp/analysis.h"
#include "lsp/index_templates.h"
#include "lsp/script_index.h"
#include "templates/builtin_templates.h"

namespace smachac::lsp {
namespace {

namespace fs = std::filesystem;

struct Indexed {
  std::unique_ptr<Analysis> analysis;
  std::unique_ptr<ScriptIndex> index;
};

Indexed indexOf(const std::string& text, const std::string& path = "/nonexistent/index.yml") {
  Document document{"file://" + path, path, "", text, 1};
  Indexed indexed;
  indexed.analysis = analyze(document, Settings{}, frontend::DocumentOverlay{});
  indexed.index = std::make_unique<ScriptIndex>(*indexed.analysis);
  return indexed;
}

bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// The occurrence at the start of the `nth` word `token` on line `line` (0-based).
const Occurrence* at(const Indexed& indexed, uint32_t line, std::string_view token, int nth = 0) {
  std::string_view text = indexed.analysis->lines().lineText(line);
  for (size_t column = text.find(token); column != std::string_view::npos;
       column = text.find(token, column + 1)) {
    bool before = column > 0 && isWordChar(text[column - 1]);
    bool after = column + token.size() < text.size() && isWordChar(text[column + token.size()]);
    if (before || after || nth-- > 0) continue;
    return indexed.index->at({line, static_cast<uint32_t>(column)});
  }
  FAIL("no word `" << token << "` on line " << line);
  return nullptr;
}

/// "line:column" (1-based, as SourceLoc) of each occurrence, separated by spaces.
std::string where(const std::vector<const Occurrence*>& occurrences) {
  std::string out;
  for (const Occurrence* o : occurrences) {
    out += (out.empty() ? "" : " ") + std::to_string(o->loc.line) + ":" +
           std::to_string(o->loc.column);
  }
  return out;
}

const char* const kInterface = R"(name: t
template: Base
outcomes: [done]
userdata: {a: 1}
states:
  - C:
      template: StateMachine
      outcomes: [ok]
      input_keys: [a, b]
      remapping: {b: a}
      userdata: {b: 0}
      transitions: {ok: done}
      states:
        - L:
            template: PrintUserdataState
            input_keys: [a, b]
            transitions: {succeeded: ok}
)";

TEST_CASE("an unremapped key of a container is one key inside and out; a remapped one is fed") {
  Indexed indexed = indexOf(kInterface);
  const Occurrence* a = at(indexed, 15, "a");
  REQUIRE(a);
  CHECK(indexed.index->symbol(a->symbol).kind == SymbolKind::UserdataKey);
  CHECK(where(indexed.index->definitions(a->symbol)) == "4:12");
  CHECK(where(indexed.index->occurrences(a->symbol)) == "4:12 9:20 10:22 16:26");
  const Occurrence* b = at(indexed, 15, "b");
  REQUIRE(b);
  // C's own `b`: its default inside, then the parent's `a` it is copied from.
  CHECK(where(indexed.index->definitions(b->symbol)) == "11:18 4:12");
  CHECK(where(indexed.index->occurrences(b->symbol)) == "9:23 10:19 11:18 16:29");
  CHECK(a->scope == b->scope);  // both read in C's scope
}

const char* const kWrites = R"(name: t
template: Base
outcomes: [done]
states:
  - C:
      template: StateMachine
      outcomes: [ok]
      output_keys: [r]
      transitions: {ok: R}
      states:
        - W:
            template: CallbacksState
            output_keys: [s]
            remapping: {s: r}
            callbacks: {s: !expr '1'}
            transitions: {succeeded: ok}
  - R:
      template: PrintUserdataState
      input_keys: [r]
      transitions: {succeeded: done}
)";

TEST_CASE("a leaf's output is a definition; a container's output keys are not") {
  Indexed indexed = indexOf(kWrites);
  REQUIRE_FALSE(indexed.index->at({18, 18}));  // the bracket is no name
  const Occurrence* read = at(indexed, 18, "r");
  REQUIRE(read);
  CHECK(where(indexed.index->definitions(read->symbol)) == "14:28");
  const Occurrence* container_output = at(indexed, 7, "r");
  REQUIRE(container_output);
  CHECK(container_output->role == Role::Reference);
  CHECK(container_output->symbol == read->symbol);
  const Occurrence* own = at(indexed, 12, "s");
  REQUIRE(own);
  CHECK(own->role == Role::Definition);
  CHECK(own->site == Site::OutputKeys);
  CHECK(indexed.index->symbol(own->symbol).name == "s");
  const Occurrence* value = at(indexed, 13, "r");
  REQUIRE(value);
  CHECK(value->site == Site::RemapValue);
  CHECK(value->role == Role::Definition);
}

const char* const kParams = R"(name: t
template: Base
outcomes: [done]
params: {p: 1, q: 2}
states:
  - C:
      template: StateMachine
      outcomes: [ok]
      params: {p: 3}
      transitions: {ok: done}
      states:
        - L:
            template: PrintUserdataState
            userdata: {v: [[p]], w: [params, q], s: [x, [[p]]], u: [[nope]]}
            input_keys: [v, w, s, u]
            transitions: {succeeded: ok}
)";

TEST_CASE("a lookup reads the nearest params entry, also inside a string construct") {
  Indexed indexed = indexOf(kParams);
  const ScriptIndex& index = *indexed.index;
  const Occurrence* p = at(indexed, 13, "p");
  REQUIRE(p);
  CHECK(p->site == Site::Lookup);
  CHECK(where(index.definitions(p->symbol)) == "9:16");
  const Occurrence* q = at(indexed, 13, "q");
  REQUIRE(q);
  CHECK(where(index.definitions(q->symbol)) == "4:16");
  const Occurrence* in_construct = at(indexed, 13, "p", 1);
  REQUIRE(in_construct);
  CHECK(in_construct->symbol == p->symbol);
  CHECK(where(index.occurrences(p->symbol)) == "9:16 14:29 14:59");
  const Occurrence* undefined = at(indexed, 13, "nope");
  REQUIRE(undefined);
  CHECK(index.definitions(undefined->symbol).empty());
  CHECK(index.symbol(undefined->symbol).kind == SymbolKind::Param);
}

TEST_CASE("positions: in a name, just after it, on whitespace, past the text") {
  Indexed indexed = indexOf(kInterface);
  const ScriptIndex& index = *indexed.index;
  const Occurrence* name = index.at({5, 4});  // `C` of `  - C:`
  REQUIRE(name);
  CHECK(name->site == Site::StateName);
  CHECK(index.at({5, 5}) == name);  // the cursor after it
  CHECK_FALSE(index.at({5, 6}));
  CHECK_FALSE(index.at({5, 3}));
  CHECK_FALSE(index.at({99, 0}));
  const Occurrence* last = index.at({1, 10});  // `Base`, at the end of its line
  REQUIRE(last);
  CHECK(index.at({1, 14}) == last);
  CHECK_FALSE(index.at({1, 15}));
  std::span<const Occurrence> document = index.document();
  for (size_t i = 1; i < document.size(); ++i) {
    const SourceLoc& a = document[i - 1].loc;
    const SourceLoc& b = document[i].loc;
    CHECK((a.line < b.line || (a.line == b.line && a.column + a.length <= b.column)));
  }
}

TEST_CASE("a document that does not parse, or is no script, has an empty index") {
  for (const char* text : {"name: t\noutcomes: [done\nstates:\n", "", "just text", "[1, 2]"}) {
    Indexed indexed = indexOf(text);
    CHECK(indexed.index->document().empty());
    CHECK_FALSE(indexed.index->at({0, 0}));
  }
}

TEST_CASE("a sub-script edited on its own: its state, names and lookups, each once") {
  Indexed indexed = indexOf(R"(- GREET:
    template: StateMachine
    params: {who: Bob}
    outcomes: [greeted]
    input_keys: [name]
    states:
      - SAY:
          template: PrintUserdataState
          userdata: {text: [[who]]}
          input_keys: [text, name]
          transitions: {succeeded: greeted}
)");
  const ScriptIndex& index = *indexed.index;
  const Occurrence* outcome = at(indexed, 10, "greeted");
  REQUIRE(outcome);
  CHECK(where(index.definitions(outcome->symbol)) == "4:16");
  const Occurrence* who = at(indexed, 8, "who");
  REQUIRE(who);
  CHECK(where(index.definitions(who->symbol)) == "3:14");
  const Occurrence* name = at(indexed, 9, "name");
  REQUIRE(name);
  CHECK(where(index.occurrences(name->symbol)) == "5:18 10:30");
}

TEST_CASE("names in a sub-script are outside the document; definitions lead there") {
  std::string path = SMACHAC_SOURCE_DIR "/tests/lsp/sessions/scripts/nav_main.yml";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  Indexed indexed = indexOf(text.str(), path);
  const ScriptIndex& index = *indexed.index;
  for (const Occurrence& o : index.document()) CHECK(o.loc.file == indexed.analysis->file);
  const Occurrence* greeted = at(indexed, 35, "greeted");
  REQUIRE(greeted);
  std::vector<const Occurrence*> definitions = index.definitions(greeted->symbol);
  REQUIRE(definitions.size() == 1);
  CHECK(definitions[0]->loc.file != indexed.analysis->file);
  CHECK(indexed.analysis->sources.path(definitions[0]->loc.file).ends_with("nav_greet.yml"));
  const Occurrence* script = at(indexed, 33, "nav_sub");
  REQUIRE(script);
  CHECK(index.symbol(script->symbol).kind == SymbolKind::SubScript);
  CHECK(index.symbol(script->symbol).file == definitions[0]->loc.file);
}

/// Sets an environment variable for one test, and puts back its old value.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_) {
      setenv(name_, old_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

fs::path freshDir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("smachac-index-test-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string contentOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string_view builtin(std::string_view path) {
  for (const EmbeddedFile& file : templates::builtinTemplates()) {
    if (file.path == path) return file.content;
  }
  return {};
}

TEST_CASE("a built-in template's file is a read-only copy in the cache, replaced if it differs") {
  fs::path cache = freshDir("cache");
  ScopedEnv xdg("XDG_CACHE_HOME", cache.string());
  TemplateFinder finder(Settings{});
  std::optional<fs::path> file = finder.file("PrintUserdataState");
  REQUIRE(file);
  fs::path expected = cache / "smachac" / std::string(kVersion) / "templates" / "smach" /
                      "PrintUserdataState.tpl.py";
  CHECK(*file == expected);
  CHECK(contentOf(*file) == builtin("smach/PrintUserdataState.tpl.py"));
  CHECK((fs::status(*file).permissions() & fs::perms::all) ==
        (fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read));
  CHECK(writeReadOnlyCopy(*file, "other"));
  CHECK(contentOf(*file) == "other");
  CHECK(finder.file("PrintUserdataState") == file);
  CHECK(contentOf(*file) == builtin("smach/PrintUserdataState.tpl.py"));
  CHECK_FALSE(finder.file("NoSuchTemplate"));
  fs::permissions(cache, fs::perms::owner_all);
  fs::remove_all(cache);
}

TEST_CASE("the cache is under HOME when XDG_CACHE_HOME is unset or relative") {
  ScopedEnv home("HOME", "/home/someone");
  ScopedEnv xdg("XDG_CACHE_HOME", "relative/cache");
  CHECK(templateCacheDir() ==
        fs::path("/home/someone/.cache/smachac") / std::string(kVersion) / "templates");
}

TEST_CASE("a user template found in a -I directory is its own file, before a built-in one") {
  fs::path dir = freshDir("user");
  std::ofstream(dir / "PrintUserdataState.tpl.py")
      << "{% block meta %}\nname: Mine\n{% endblock meta %}\n";
  Settings settings;
  settings.template_dirs = {dir.string()};
  TemplateFinder finder(settings);
  CHECK(finder.file("PrintUserdataState") == dir / "PrintUserdataState.tpl.py");
  CHECK(finder.documentation("PrintUserdataState") == "### Template `Mine`");
  fs::remove_all(dir);
}

const char* const kMeta = R"(name: Demo
description: Does things.
variables:
  - speed: {description: How fast., type: float}
  - [{label: {description: A label., type: [str, int]}}]
  - [{a: {type: int}}, {b: {type: str}}]
  - group: [{x: {type: int}}]
outcomes: [done]
)";

TEST_CASE("a meta block as help text and as markdown: the same parts, laid out for each") {
  tmpl::Value meta = tmpl::parseYaml(kMeta, "test");
  CHECK(backends::templateHelpText(meta, {}) == R"(Template: Demo
Description: Does things.
Variables:
    speed: How fast.
        Type: float
    label (optional): A label.
        Type: str or int
    Option:
        a
            Type: int
        b
            Type: str
    group:
        x
            Type: int
Outcomes:
    done
)");
  CHECK(backends::templateHelpMarkdown(meta) == R"(### Template `Demo`

**Description:** Does things.

**Variables:**

- `speed`: How fast.
  - Type: `float`
- `label` (optional): A label.
  - Type: `str or int`
- *Option:*
  - `a`
    - Type: `int`
  - `b`
    - Type: `str`
- *group:*
  - `x`
    - Type: `int`

**Outcomes:**

- `done`)");
}

}  // namespace
}  // namespace smachac::lsp
