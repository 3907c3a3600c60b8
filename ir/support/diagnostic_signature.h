// DiagSignature<Params...>: the argument types that a diagnostic kind or note kind declares
// (the last column of diagnostic_kinds.def and diagnostic_notes.def), and the compile-time
// checks of a call against them. A call gives exactly one argument per declared type, each
// converting implicitly and without narrowing (a std::string or a literal for a
// std::string_view, a size_t for a uint64_t; not an int for a size_t, nor a number for text);
// fmt checks the message format against the declared types (fmt::format_string).
#pragma once

#include <fmt/core.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>

#include "ir/support/diagnostic_arg_types.h"

namespace smachac {

/// True when `Given` passes as a `Param`: implicitly, and without narrowing.
template <typename Given, typename Param>
concept DiagArgumentFor = std::is_convertible_v<const Given&, Param> &&
    requires(const Given& given) {
  Param{given};
};

template <typename... Params>
struct DiagSignature {
  static constexpr size_t kCount = sizeof...(Params);

  template <typename... Given>
  static constexpr bool accepts() {
    if constexpr (sizeof...(Given) != kCount) {
      return false;
    } else {
      return (DiagArgumentFor<Given, Params> && ...);
    }
  }

  /// The message: `format` is checked against the declared types when the call is compiled.
  static std::string format(fmt::format_string<const Params&...> format, const Params&... args) {
    return fmt::format(format, args...);
  }

  /// Runs fmt's check of the format that `Format` (a lambda without captures) returns against
  /// the declared types: a format that does not suit them stops the compilation, else true.
  /// For a .def entry that no call uses yet (diagnostic.cpp checks every entry).
  template <typename Format>
  static constexpr bool checks(Format) {
    [[maybe_unused]] fmt::format_string<const Params&...> checked(Format{}());
    return true;
  }
};

}  // namespace smachac

/// The parenthesised type list of a .def entry, unwrapped: SMACHAC_DIAG_TYPES((A, B)) is A, B.
#define SMACHAC_DIAG_UNWRAP(...) __VA_ARGS__
#define SMACHAC_DIAG_TYPES(types) SMACHAC_DIAG_UNWRAP types
