// What a compile command line says (`smachac [-target=T] script.yml [-o out]` and the rest of
// compile_command.cpp's options), filled by CLI11 or, for the common lines, by quick_args.h.
#pragma once

#include <string>

#include "tools/smachac/script_inputs.h"
#include "tools/smachac/session.h"

namespace smachac::driver {

struct CompileOptions {
  CommonOptions common;
  ScriptInputs scripts;
  std::string output;
  std::string depfile;
  std::string emit;
  bool syntax_only = false;
  bool comments = false;
  bool introspection = false;
  bool list_targets = false;
  int flexbe_ros = 2;
};

}  // namespace smachac::driver
