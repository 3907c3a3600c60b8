// The ANSI styles of `smachac help`, all empty for plain text.
#pragma once

#include <string>

namespace smachac::driver {

struct HelpStyle {
  std::string title, heading, name, type, reset;
  explicit HelpStyle(bool ansi)
      : title(ansi ? "\033[1;4;32m" : ""),
        heading(ansi ? "\033[1;35m" : ""),
        name(ansi ? "\033[1;34m" : ""),
        type(ansi ? "\033[33m" : ""),
        reset(ansi ? "\033[0m" : "") {}
};

}  // namespace smachac::driver
