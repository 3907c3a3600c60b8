// The build's images of the built-in templates (backends/tmpl/image/): every built-in template
// that compiles has one, the template loaded from it is the one compiled from its source
// (a dump of the whole AST, scope analysis and every macro included), the build's bytes are
// what the writer makes of the compiled template, and an image that does not fit (corrupted,
// of another source, naming a filter the environment lacks) is refused for the source.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "backends/tmpl/environment.h"
#include "backends/tmpl/image/image_writer.h"
#include "backends/tmpl/template.h"
#include "templates/builtin_templates.h"
#include "tests/unit/backends/tmpl/ast_dump.h"
#include "tools/cmake/target_extensions.h"

namespace smachac::tmpl {
namespace {

using testing::dumpWhole;

std::string setOf(std::string_view path) { return std::string(path.substr(0, path.find('/') + 1)); }

/// The built-in table with `path`'s image replaced by `image`.
std::vector<EmbeddedFile> withImage(std::string_view path, std::span<const uint8_t> image) {
  std::span<const EmbeddedFile> builtins = templates::builtinTemplates();
  std::vector<EmbeddedFile> files(builtins.begin(), builtins.end());
  for (EmbeddedFile& file : files) {
    if (file.path == path) file.image = image;
  }
  return files;
}

/// One built-in template compiled in an environment of its set, from `files`.
class Compiled {
 public:
  Compiled(std::string_view path, std::span<const EmbeddedFile> files, bool extensions = true)
      : env_({}, {setOf(path)}, files) {
    if (extensions) build::registerSetExtensions(env_, setOf(path), converter_);
    name_ = std::string(path.substr(path.find('/') + 1));
  }
  const Template& get() { return env_.compiled(name_); }

 private:
  generator::ValueConverter converter_;
  Environment env_;
  std::string name_;
};

TEST_CASE("every built-in template's image loads as the template compiled from its source") {
  size_t loaded = 0;
  for (const EmbeddedFile& file : templates::builtinTemplates()) {
    CAPTURE(file.path);
    std::vector<EmbeddedFile> without = withImage(file.path, {});
    Compiled parsed(file.path, without);
    if (file.image.empty()) {  // only a template that does not compile with its set's filters
      CHECK_THROWS(parsed.get());
      continue;
    }
    Compiled from_image(file.path, templates::builtinTemplates());
    const Template& image_template = from_image.get();
    const Template& source_template = parsed.get();
    REQUIRE(image_template.loadedFromImage());
    REQUIRE_FALSE(source_template.loadedFromImage());
    std::string expected = dumpWhole(source_template);
    CHECK(dumpWhole(image_template) == expected);
    // The build wrote what the writer makes of the compiled template (deterministic bytes).
    Compiled again(file.path, without);
    std::vector<uint8_t> written = writeTemplateImage(again.get());
    CHECK(std::vector<uint8_t>(file.image.begin(), file.image.end()) == written);
    ++loaded;
  }
  CHECK(loaded + 1 >= templates::builtinTemplates().size());  // dot/'s filter is the dot target's
}

const EmbeddedFile& builtin(std::string_view path) {
  for (const EmbeddedFile& file : templates::builtinTemplates()) {
    if (file.path == path) return file;
  }
  FAIL("no built-in " << path);
  throw;
}

TEST_CASE("an image that does not fit is refused and the source compiled") {
  const EmbeddedFile& utils = builtin("smach/Utils.tpl.py");
  REQUIRE_FALSE(utils.image.empty());
  std::string expected = dumpWhole(Compiled(utils.path, withImage(utils.path, {})).get());
  auto refused = [&](std::vector<uint8_t> image) {
    std::vector<EmbeddedFile> files = withImage(utils.path, image);
    Compiled compiled(utils.path, files);
    const Template& t = compiled.get();
    return !t.loadedFromImage() && dumpWhole(t) == expected;
  };
  std::vector<uint8_t> bytes(utils.image.begin(), utils.image.end());
  CHECK_FALSE(refused(bytes));  // the image itself loads
  for (size_t at : {size_t(0), size_t(4), size_t(6), size_t(12), size_t(20), bytes.size() / 2,
                    bytes.size() - 1}) {
    CAPTURE(at);
    std::vector<uint8_t> corrupted = bytes;
    corrupted[at] ^= 0x10;
    CHECK(refused(corrupted));
  }
  CHECK(refused(std::vector<uint8_t>(bytes.begin(), bytes.end() - 1)));
  CHECK(refused(std::vector<uint8_t>(bytes.begin(), bytes.begin() + 10)));
  const EmbeddedFile& base = builtin("smach/Base.tpl.py");
  CHECK(refused(std::vector<uint8_t>(base.image.begin(), base.image.end())));  // another source
}

TEST_CASE("an image naming a filter the environment lacks gives the source's error") {
  // smach/Utils.tpl.py uses the Python target's filters: without them it does not compile.
  const EmbeddedFile& utils = builtin("smach/Utils.tpl.py");
  std::vector<EmbeddedFile> without = withImage(utils.path, {});
  std::string from_source;
  std::string from_image;
  try {
    Compiled(utils.path, without, false).get();
  } catch (const TemplateError& e) {
    from_source = e.what();
  }
  try {
    Compiled(utils.path, templates::builtinTemplates(), false).get();
  } catch (const TemplateError& e) {
    from_image = e.what();
  }
  CHECK_FALSE(from_source.empty());
  CHECK(from_image == from_source);
}

}  // namespace
}  // namespace smachac::tmpl
