// The output targets of `smachac -target=NAME`: each turns a checked module into files.
// Text targets (ir, json) print the IR; code targets render templates through the generator.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"

namespace smachac::backends {

/// `-emit=library` (C++ target): the generated pair's file names (the source includes the
/// header by this name) and the namespace of its declarations.
struct LibraryNames {
  std::string source;      ///< e.g. `seq.cpp`
  std::string header;      ///< e.g. `seq.h`
  std::string name_space;  ///< e.g. `seq`
};

struct EmitOptions {
  std::vector<std::string> template_dirs;  ///< -I, searched before the built-in templates
  bool comments = false;                   ///< -c
  bool introspection = false;              ///< -i
  int flexbe_ros = 2;                      ///< -flexbe-ros (FlexBE target: ROS 1 or 2)
  std::string output;                      ///< -o (a target may read what is there)
  std::optional<LibraryNames> library;     ///< -emit=library; nullopt: -emit=program
};

/// One generated file. An empty `name` is the file named by -o (or stdout); otherwise a
/// path relative to the -o directory.
struct OutputFile {
  std::string name;
  std::string content;
};

struct EmitContext {
  SourceManager& sources;  ///< code targets add the templates that diagnostics quote
  DiagnosticEmitter& diags;
  const EmitOptions& options;
};

/// A target takes the module: it may free it as soon as it no longer reads it (the SMACH
/// target frees the IR before its base render, so that a big script's IR and its generated code
/// are not held at the same time).
using EmitFn = std::optional<std::vector<OutputFile>> (*)(ir::Module&&, EmitContext&);

/// The template blocks a SMACH-shaped target (smach, cpp) leaves out: the comment blocks
/// without -c, the introspection server and its spin without -i.
std::vector<std::string> optionalBlocksSkipped(const EmitOptions& options);

struct Target {
  std::string_view name;
  std::string_view description;
  EmitFn emit;
};

std::span<const Target> targets();
const Target* findTarget(std::string_view name);

}  // namespace smachac::backends
