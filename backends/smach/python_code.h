// Python source text for template values, so that generated Python compiles and holds exactly
// the script's values:
//   pythonLiteral   a Python expression equal to a value: repr(), except that non-finite floats
//                   (whose repr `nan`/`inf` is no Python expression) become float('nan'), ...
//   pythonCode      SMACHA's bare rendering of values its `not_string` test accepts: strings
//                   that read as a number literal, a dotted name or one call (a name or
//                   dotted name, then arguments closing at the end) are code, written
//                   bare; strings that `not_string` accepts but that would not compile as
//                   written (`1.2.3`, `nan`, `012`, `a.if`) are quoted instead
//   pythonComment   text that stays on one `#` comment line: line breaks, control and other
//                   non-printable characters escaped as repr() escapes them
//   identifierPart  text usable inside an identifier: bytes other than [A-Za-z0-9_] as `_xHH`
#pragma once

#include <string>
#include <string_view>

#include "backends/tmpl/values/value.h"

namespace smachac::backends::smach {

std::string pythonLiteral(const tmpl::Value& value);
std::string pythonCode(const tmpl::Value& value);
std::string pythonComment(std::string_view text);
std::string identifierPart(std::string_view text);

}  // namespace smachac::backends::smach
