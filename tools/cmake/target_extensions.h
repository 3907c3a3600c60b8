// The filters, tests and globals a built-in template set is compiled with, for the build tools
// that compile built-in templates (meta_table_gen.cpp, embed_gen.cpp): cpp/ gets C++'s, every
// other set Python's, as backends/meta/template_check.cpp registers them. Rule: `converter` must
// outlive the environment's renders.
#pragma once

#include <string_view>

#include "backends/cpp/cpp_extensions.h"
#include "backends/smach/python_extensions.h"
#include "backends/tmpl/environment.h"

namespace smachac::build {

inline void registerSetExtensions(tmpl::Environment& env, std::string_view set,
                                  const generator::ValueConverter& converter) {
  if (set == "cpp/") {
    backends::cpp::registerCppExtensions(env, converter, false);
  } else {
    backends::smach::registerPythonExtensions(env, converter, false);
  }
}

}  // namespace smachac::build
