// Reading the common compile command lines without CLI11 (see quick_args.h for the rules).
#include "tools/smachac/quick_args.h"

#include <string_view>

namespace smachac::driver {
namespace {

enum class Slot {
  Target,
  Output,
  TemplateDir,
  ScriptDir,
  SyntaxOnly,
  Comments,
  Introspection,
  Optimize
};

struct Spelling {
  std::string_view text;
  Slot slot;
};

// As compile_command.cpp and session.cpp declare them to CLI11 (after normalizeArgs).
constexpr Spelling kSpellings[] = {
    {"--target", Slot::Target},
    {"-o", Slot::Output},
    {"--output", Slot::Output},
    {"-I", Slot::TemplateDir},
    {"--template-dir", Slot::TemplateDir},
    {"-S", Slot::ScriptDir},
    {"--script-dir", Slot::ScriptDir},
    {"--fsyntax-only", Slot::SyntaxOnly},
    {"-c", Slot::Comments},
    {"--comments", Slot::Comments},
    {"-i", Slot::Introspection},
    {"--introspection", Slot::Introspection},
    {"-O", Slot::Optimize},
    {"--optimize", Slot::Optimize},
};

const Spelling* findSpelling(std::string_view text) {
  for (const Spelling& s : kSpellings) {
    if (s.text == text) return &s;
  }
  return nullptr;
}

bool takesValue(Slot slot) { return slot <= Slot::ScriptDir; }
bool repeatable(Slot slot) { return slot == Slot::TemplateDir || slot == Slot::ScriptDir; }

class QuickReader {
 public:
  std::optional<CompileOptions> read(const Args& args) {
    for (size_t i = 0; i < args.size(); ++i) {
      const std::string& arg = args[i];
      if (arg.empty()) return std::nullopt;
      if (arg.front() != '-') {
        options_.scripts.inputs.push_back(arg);
      } else if (!readOption(args, i)) {
        return std::nullopt;
      }
    }
    return std::move(options_);
  }

 private:
  // The option at args[i] (`--name=V`, or its value in the next argument); false when the
  // line must go to CLI11 instead.
  bool readOption(const Args& args, size_t& i) {
    std::string_view name = args[i];
    std::optional<std::string> value;
    if (size_t eq = name.find('='); name.starts_with("--") && eq != std::string_view::npos) {
      value = std::string(name.substr(eq + 1));
      name = name.substr(0, eq);
    }
    const Spelling* spelling = findSpelling(name);
    if (!spelling) return false;
    if (takesValue(spelling->slot) && !value) {
      if (i + 1 >= args.size()) return false;
      value = args[++i];
    }
    return store(spelling->slot, value);
  }

  // Stores one option; false when the line must go to CLI11 instead.
  bool store(Slot slot, const std::optional<std::string>& value) {
    unsigned bit = 1u << static_cast<unsigned>(slot);
    if ((seen_ & bit) != 0 && !repeatable(slot)) return false;
    seen_ |= bit;
    if (takesValue(slot) != value.has_value()) return false;
    if (value && (value->empty() || value->front() == '-')) return false;
    switch (slot) {
      case Slot::Target:
        options_.common.target = *value;
        break;
      case Slot::Output:
        options_.output = *value;
        break;
      case Slot::TemplateDir:
        options_.common.template_dirs.push_back(*value);
        break;
      case Slot::ScriptDir:
        options_.common.script_dirs.push_back(*value);
        break;
      case Slot::SyntaxOnly:
        options_.syntax_only = true;
        break;
      case Slot::Comments:
        options_.comments = true;
        break;
      case Slot::Introspection:
        options_.introspection = true;
        break;
      case Slot::Optimize:
        options_.common.optimize = true;
        break;
    }
    return true;
  }

  CompileOptions options_;
  unsigned seen_ = 0;
};

}  // namespace

std::optional<CompileOptions> readQuickCompileLine(const Args& args) {
  return QuickReader().read(args);
}

}  // namespace smachac::driver
