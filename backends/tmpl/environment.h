// The template engine's public API. An Environment finds templates (user directories, then
// built-in sets), compiles each once, and renders them with SMACHA's Jinja2 settings
// (lstrip_blocks, no trim_blocks, `do`, SMACHA's tests and filter). It also provides the
// operations SMACHA's generator needs: rendering one block in isolation, listing blocks,
// exporting module variables and reading the `meta` block. See backends/tmpl/README.md.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/tmpl/error.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/limits.h"
#include "backends/tmpl/renderer/call_args.h"
#include "backends/tmpl/values/value.h"
#include "ir/support/embedded_file.h"

namespace smachac::tmpl {

class EnvironmentImpl;
class Template;

struct RenderOptions {
  /// Blocks removed from every template of the render, with their contents, as if absent
  /// (SMACHA's SkipBlockExtension; e.g. `meta`, `upper_comments`, `spin`).
  std::vector<std::string> skip_blocks;
};

class Environment {
 public:
  /// `templateDirs` are searched in order before the built-in sets, which are prefixes into
  /// `builtins`, the caller's table of embedded templates (e.g. {"smach/", "smach_ros/"}):
  /// the engine knows no templates of its own.
  Environment(std::vector<std::string> template_dirs, std::vector<std::string> builtin_sets,
              std::span<const EmbeddedFile> builtins);
  ~Environment();
  Environment(const Environment&) = delete;

  /// From now on every Environment destroyed leaves its memory to the end of the process
  /// instead of freeing it: for a process that exits as soon as its work is written (the
  /// driver's compile), never for one that keeps running or checks for leaks.
  static void leaveToProcessExit();

  Environment& operator=(const Environment&) = delete;

  /// Renders template `name` (an exact template name) with `context` (a dict).
  std::string render(std::string_view name, const Value& context,
                     const RenderOptions& options = {});

  /// Renders the whole template with every other block of it (and of everything it extends,
  /// includes or imports) removed, then strips the result and appends "\n" if non-empty.
  std::string renderBlock(std::string_view name, std::string_view block, const Value& context,
                          const RenderOptions& options = {});

  /// The sorted names of the blocks of `name` and of every template it references through
  /// extends, include, import and from-import (string literals), recursively.
  std::vector<std::string> listBlocks(std::string_view name);

  /// The exported top-level variables and macros of `name` after running it with `context`,
  /// sorted by name (names starting with `_` are never exported).
  std::vector<std::pair<std::string, Value>> moduleVariables(std::string_view name,
                                                             const Value& context,
                                                             const RenderOptions& options = {});

  /// The text of the template's own `meta` block rendered with an empty context, or nullopt.
  std::optional<std::string> metaBlock(std::string_view name);

  /// Resolves a script-level template name: in each directory (then each built-in set) in
  /// order, `Foo`, `Foo.tpl.py`, `Foo.tpl`, then the first `Foo.tpl.<ext>` alphabetically.
  std::optional<std::string> resolveScriptTemplate(std::string_view name) const;
  bool hasTemplate(std::string_view name) const;
  /// Template `name` compiled (once; raises Fault if there is none, TemplateError if it does
  /// not compile): for the build's images of the
  /// built-in templates (image/image_writer.h) and the tests that compare them.
  const Template& compiled(std::string_view name);

  /// Adds an in-memory template, found before any directory (tests, generated templates).
  void addTemplate(std::string name, std::string source);

  /// Replaces the bounds on every later render (steps, string and container sizes); a render
  /// that exceeds one fails with a located TemplateError. Fuzzers set small ones.
  void setLimits(const Limits& limits);

  void addFilter(std::string name, CustomFilter fn);
  void addTest(std::string name, CustomTest fn);
  void addGlobal(std::string name, Value value);

 private:
  std::unique_ptr<EnvironmentImpl> impl_;
};

}  // namespace smachac::tmpl
