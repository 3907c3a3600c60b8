// What the SMACH target adds to the template language for Python output:
//   filter `pyrepr`          Python's repr(): a string becomes a correctly escaped string
//                            literal ('it''s' → "it's", backslashes and control characters
//                            escaped); other values print as Python would show them in a list
//   filter `pyliteral`       a Python expression equal to the value (repr(), with non-finite
//                            floats as float('nan'), float('inf'), -float('inf'))
//   filter `pycode`          a value SMACHA's `not_string` accepts, bare when it compiles as
//                            written (number literal, dotted name, call), else quoted
//   filter `pycomment`       text that stays on its `#` comment line (non-printable escaped)
//   filter `pyident`         text usable inside an identifier (other bytes as `_xHH`)
//   (python_code.h has the rules)
//   test `forced_string`     the value is a string the script tagged `!str`: always quote it
//   global `include_comments` true with -c: the built-in templates then add comment lines
#pragma once

#include "backends/generator/template_values.h"
#include "backends/tmpl/environment.h"

namespace smachac::backends::smach {

/// Registers the filters, test and global in `env`; `converter` must outlive `env`'s renders.
void registerPythonExtensions(tmpl::Environment& env, const generator::ValueConverter& converter,
                              bool include_comments);

}  // namespace smachac::backends::smach
