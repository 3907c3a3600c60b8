// What the C++ target adds to the template language for C++ output:
//   filter `cppstr`    a C++ string literal for any value's text: `"` and `\` escaped, control
//                      characters and every byte >= 0x80 written as 3-digit octal escapes, so
//                      the literal holds exactly the value's bytes whatever the source charset
//   filter `cppvalue`  a C++ expression that converts to `smachac::runtime::Value`: None →
//                      `nullptr`, bools, `int64_t{n}`, doubles (round-trip precision, inf and
//                      nan through std::numeric_limits), strings as `std::string(...)`, lists
//                      as `rt::List{...}`, dicts as `rt::Map{{"k", v}, ...}`; a backtick
//                      expression ("`code`") is written bare: it is C++ already
//                      (a `!str` string is a string even when written in backticks)
//   filter `cppuserdata` a value as a container's `userdata().set(key, ...)` takes it: a string
//                      that `cppvalue` writes as `std::string("...")` is a bare string literal
//                      (the store's `set(key, const char*)`: nothing to destroy at the call),
//                      anything else as `cppvalue` writes it
//   filter `cppcomment` text that stays on its `//` comment line: control characters and
//                      backslashes as octal escapes (no line break, no line splice)
//   test `forced_string`     the value is a string the script tagged `!str`
//   global `include_comments` true with -c
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "backends/generator/template_values.h"
#include "backends/tmpl/environment.h"

namespace smachac::backends::cpp {

/// `"..."`: a C++ string literal holding exactly the bytes of `text`.
std::string cppStringLiteral(std::string_view text);

/// Whether a string value is one the script tagged `!str`.
using IsForcedString = std::function<bool(const tmpl::Value&)>;

/// A C++ expression converting to a runtime Value (see `cppvalue` above).
std::string cppValueExpression(const tmpl::Value& value, const IsForcedString& forced);

/// The same, for values without `!str` strings.
std::string cppValueExpression(const tmpl::Value& value);

/// The argument of a userdata store's `set` (see `cppuserdata` above).
std::string cppUserdataArgument(const tmpl::Value& value, const IsForcedString& forced);

/// The text of a `//` comment for `text` (see `cppcomment` above).
std::string cppCommentText(std::string_view text);

/// Registers the filters, test and global in `env`; `converter` must outlive `env`'s renders.
void registerCppExtensions(tmpl::Environment& env, const generator::ValueConverter& converter,
                           bool include_comments);

}  // namespace smachac::backends::cpp
