// What the SMACH target adds to the template language for Python output:
//   filter `pyrepr`          Python's repr(): a string becomes a correctly escaped string
//                            literal ('it''s' → "it's", backslashes and control characters
//                            escaped); other values print as Python would show them in a list
//   test `forced_string`     the value is a string the script tagged `!str`: always quote it
//   global `include_comments` true with -c: the built-in templates then add comment lines
#pragma once

#include "backends/generator/template_values.h"
#include "backends/tmpl/environment.h"

namespace smachac::backends::smach {

/// Registers the filter, test and global in `env`; `converter` must outlive `env`'s renders.
void registerPythonExtensions(tmpl::Environment& env, const generator::ValueConverter& converter,
                              bool include_comments);

}  // namespace smachac::backends::smach
