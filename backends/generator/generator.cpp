// The recursive walk: root level, leaves, containers, and the base render.
#include "backends/generator/generator.h"

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <initializer_list>
#include <set>
#include <tuple>
#include <utility>

#include "backends/generator/code_buffers.h"
#include "backends/generator/state_uuid.h"
#include "backends/generator/state_variables.h"
#include "backends/generator/template_runner.h"
#include "ir/support/suggest.h"

namespace smachac::generator {
namespace {

/// One level of the script (the root or a container's children): SMACHA's script_vars.
struct Level {
  tmpl::Value vars = tmpl::Value::newDict();  ///< every non-buffer variable
  CodeBuffers buffers;
  std::string container;  ///< the key of this level's snippets in keyed buffers
};

std::string asciiLower(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

tmpl::Value str(std::string_view text) { return tmpl::Value::string(std::string(text)); }

const std::string& templateText(const ir::State& state) {
  static const std::string kNone;
  return state.template_name ? state.template_name->text.str() : kNone;
}

class Generator {
 public:
  Generator(const ir::Module& module, GeneratorContext& context)
      : module_(module),
        ctx_(context),
        runner_(context.env, context.path, context.skip_blocks),
        files_(context.sources, context.path.builtins) {}

  /// A generator that owns the module and frees it before the base render.
  Generator(ir::Module&& module, GeneratorContext& context)
      : owned_(std::move(module)),
        module_(*owned_),
        ctx_(context),
        runner_(context.env, context.path, context.skip_blocks),
        files_(context.sources, context.path.builtins) {}

  std::optional<std::string> run() {
    const ir::State& root = module_.state(module_.root());
    std::optional<std::string> base = resolve(root);
    if (!base) return std::nullopt;
    Level level = rootLevel(root);
    if (!guarded(root, [&] { seedFromBase(*base, root, level); })) return std::nullopt;
    processChildren(root, level);
    tmpl::Value base_variables = rootVariables(root);
    RenderNote note = noteOf(root);
    releaseModule();  // neither `root` nor `module_` is read past this point
    addBuffers(base_variables, level);
    std::string code;
    guardedWith([&] { return note; }, [&] { code = runner_.renderBase(*base, base_variables); });
    if (failed_) return std::nullopt;
    code += '\n';  // stripping left the capacity for it: no copy of the whole module
    return code;
  }

 private:
  Level rootLevel(const ir::State& root) {
    Level level;
    level.container = root.name.text;
    tmpl::DictObject& vars = level.vars.dict();
    vars.setString("parent_name", str(root.name.text));
    vars.setString("parent_sm_name", str(asciiLower(root.name.text)));
    vars.setString("parent_template", str(templateText(root)));
    vars.setString("parent_type", str("StateMachine"));
    return level;
  }

  /// The base template's globals (defined_headers pre-seeded with its own imports, ...),
  /// computed with every buffer empty.
  void seedFromBase(const std::string& base, const ir::State& root, Level& level) {
    tmpl::Value context = tmpl::Value::newDict();
    context.dict().setString("name", str(root.name.text));
    copyRootKeys(root, {"import_modules", "from_imports"}, context);  // seeded: written once
    for (const BufferSpec& spec : bufferSpecs()) {
      tmpl::Value empty = str("");
      if (spec.kind == BufferKind::Keyed) {
        empty = tmpl::Value::newDict();
        empty.dict().setString(root.name.text, str(""));
      }
      context.dict().setString(spec.name, empty);
    }
    addExports(runner_.exportsRunningBlocks(base, context), level);
  }

  /// Copies the given keys of the script's root, where present, into vars.
  void copyRootKeys(const ir::State& root, std::initializer_list<const char*> names,
                    tmpl::Value& vars) {
    tmpl::Value keys = tmpl::Value::newDict();
    addStateKeys(root, keys, ctx_.converter);
    for (const char* key : names) {
      if (const tmpl::Value* v = keys.dict().findString(key)) vars.dict().setString(key, *v);
    }
  }

  /// The base template's variables from the script's root.
  tmpl::Value rootVariables(const ir::State& root) {
    tmpl::Value vars = tmpl::Value::newDict();
    vars.dict().setString("name", str(root.name.text));
    copyRootKeys(root,
                 {"manifest", "function_name", "node_name", "outcomes", "userdata", "input_keys",
                  "output_keys", "import_modules", "from_imports"},
                 vars);
    return vars;
  }

  /// The root level's buffers, moved into the base template's variables, then its variables.
  static void addBuffers(tmpl::Value& vars, Level& level) {
    for (size_t b = 0; b < kBufferCount; ++b) {
      vars.dict().setString(bufferSpecs()[b].name, level.buffers.take(b, /*strip=*/true));
    }
    updateDict(vars, level.vars);
  }

  void processChildren(const ir::State& container, Level& level) {
    for (ir::StateId id : container.children) {
      const ir::State& state = module_.state(id);
      // A sub-script call writes the caller's params into the level.
      if (!state.included_from.empty() && state.params) {
        level.vars.dict().setString("params", ctx_.converter.convert(*state.params));
      }
      if (ir::isContainer(state.kind)) {
        processContainer(id, state, level);
      } else {
        processLeaf(id, state, level);
      }
    }
  }

  void processLeaf(ir::StateId id, const ir::State& state, Level& level) {
    std::optional<std::string> name = resolve(state);
    if (!name) return;
    tmpl::Value vars = stateVariables(state, uuid(id), ctx_.converter);
    updateDict(vars, level.vars);
    guarded(state, [&] {
      BlockCode code = runner_.renderBlocks(*name, vars);
      addExports(runner_.exports(*name, vars), level);
      for (auto& [block, snippet] : code) {
        std::optional<size_t> buffer = bufferIndex(block);
        if (buffer && !snippet.empty()) {
          level.buffers.insert(*buffer, std::move(snippet), level.container);
        }
      }
    });
  }

  void processContainer(ir::StateId id, const ir::State& state, Level& level) {
    std::optional<std::string> name = resolve(state);
    Level child = childLevel(state, level);
    processChildren(state, child);
    if (!name) return;
    tmpl::Value vars = stateVariables(state, uuid(id), ctx_.converter);
    for (size_t b = 0; b < kBufferCount; ++b) {
      vars.dict().setString(bufferSpecs()[b].name, child.buffers.value(b, /*strip=*/false));
    }
    updateDict(vars, level.vars);
    guarded(state, [&] {
      BlockCode code = runner_.renderBlocks(*name, vars);
      addExports(runner_.exports(*name, vars), level);
      propagate(state, *name, code, child, level);
    });
  }

  Level childLevel(const ir::State& state, const Level& level) {
    Level child;
    child.vars = copyDict(level.vars);
    child.container = state.name.text;
    const ir::Argument* sm_name = state.findArg("sm_name");
    std::string parent_sm_name = sm_name && sm_name->value.isString()
                                     ? sm_name->value.asString()
                                     : "sm_" + asciiLower(state.name.text);
    tmpl::DictObject& vars = child.vars.dict();
    vars.setString("parent_name", str(state.name.text));
    vars.setString("parent_sm_name", str(parent_sm_name));
    vars.setString("parent_template", str(templateText(state)));
    vars.setString("parent_type", str(templateText(state)));
    if (state.params) vars.setString("params", ctx_.converter.convert(*state.params));
    return child;
  }

  /// A container's code goes up in place of its children's for the buffers its template has
  /// blocks for; the children's code goes up unchanged for the others.
  void propagate(const ir::State& state, const std::string& name, const BlockCode& code,
                 const Level& child, Level& level) {
    for (size_t b = 0; b < kBufferCount; ++b) {
      const BufferSpec& spec = bufferSpecs()[b];
      const std::string* own = nullptr;
      for (const auto& [block, snippet] : code) {
        if (block == spec.name) own = &snippet;
      }
      if (own) {
        if (own->empty()) continue;
        if (spec.kind == BufferKind::Keyed) {
          ctx_.diags.emit<DiagKind::ContainerReplacesCollectedBlock>(state.template_name->loc, name,
                                                                     spec.name);
          failed_ = true;
          continue;
        }
        level.buffers.insert(b, *own, level.container);
      } else if (spec.kind == BufferKind::Keyed) {
        for (auto& [key, joined] : child.buffers.joinedEntries(b)) {
          level.buffers.insert(b, std::move(joined), key);
        }
      } else if (std::string joined = child.buffers.joined(b); !joined.empty()) {
        level.buffers.insert(b, std::move(joined), level.container);
      }
    }
  }

  void addExports(Exports exports, Level& level) {
    for (auto& [key, value] : exports) level.vars.dict().setString(key, std::move(value));
  }

  std::string uuid(ir::StateId id) const {
    return stateUuid(ctx_.sources.path(module_.files().front()), module_.path(id));
  }

  std::optional<std::string> resolve(const ir::State& state) {
    if (!state.template_name) return std::nullopt;  // reported by the frontend
    const ir::Name& name = *state.template_name;
    std::optional<std::string> found = runner_.resolve(name.text);
    if (found) return found;
    failed_ = true;
    // A sub-script included twice names the same template at the same place: report it once.
    if (!reported_unknown_.emplace(name.loc.file, name.loc.line, name.loc.column).second) {
      return std::nullopt;
    }
    std::optional<std::string> match = closestTemplate(name.text, ctx_.path);
    ctx_.diags.emit<DiagKind::UnknownTemplate>(name.loc, name.text, describePath(ctx_.path),
                                               didYouMean(match));
    ctx_.diags.fixIt(match);
    return std::nullopt;
  }

  /// Where a template error's note points: the state whose template raised it.
  struct RenderNote {
    SourceLoc where;
    std::string template_text;
    std::string state_name;
  };

  static RenderNote noteOf(const ir::State& state) {
    return {state.template_name ? state.template_name->loc : state.loc, templateText(state),
            state.name.text};
  }

  /// An owned module is freed, and its memory given back to the system: a big script's IR is
  /// about as large as its generated code, which the base render holds twice (in and out).
  void releaseModule() {
    if (!owned_) return;
    owned_.reset();
#ifdef __GLIBC__
    malloc_trim(0);
#endif
  }

  template <class Body>
  bool guarded(const ir::State& state, Body&& body) {
    return guardedWith([&] { return noteOf(state); }, body);
  }

  /// Runs `body`; a template error becomes a diagnostic (each distinct error once) with a
  /// note made by `make_note`.
  template <class MakeNote, class Body>
  bool guardedWith(MakeNote&& make_note, Body&& body) {
    try {
      body();
      return true;
    } catch (const tmpl::TemplateError& e) {
      failed_ = true;
      auto key = std::make_tuple(e.file(), e.line(), e.column(), e.message());
      if (!reported_errors_.insert(key).second) return false;
      ctx_.diags.emit<DiagKind::TemplateError>(files_.locate(e), ForeignMessage(e.message()));
      RenderNote note = make_note();
      ctx_.diags.note<DiagNoteKind::WhileRenderingTemplate>(note.where, note.template_text,
                                                            note.state_name);
      return false;
    }
  }

  std::optional<ir::Module> owned_;
  const ir::Module& module_;
  GeneratorContext& ctx_;
  TemplateRunner runner_;
  TemplateFiles files_;
  bool failed_ = false;
  std::set<std::tuple<uint32_t, uint32_t, uint32_t>> reported_unknown_;
  std::set<std::tuple<std::string, int, int, std::string>> reported_errors_;
};

}  // namespace

std::optional<std::string> generate(const ir::Module& module, GeneratorContext& context) {
  return Generator(module, context).run();
}

std::optional<std::string> generate(ir::Module&& module, GeneratorContext& context) {
  return Generator(std::move(module), context).run();
}

}  // namespace smachac::generator
