// Writes the FlexBE behaviors of a script: its own and one per embedded sub-script
// (embedded_behaviors.h), each rendered by SMACHA's generator from its Base root with these
// globals for the base template:
//   behavior_parameters  [{name, value}]: the behavior's parameters and their defaults
//   contained_behaviors  [{name, id}]: the behaviors it embeds, for add_behavior and the manifest
//   main_behavior        the script's name: every behavior goes to its package
// A sub-script included several times is one behavior when its instances differ only in the
// values of its parameters; otherwise each different instance is a behavior of its own,
// named after the sub-script with a number (`pick_block_2`).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "backends/generator/generator.h"
#include "backends/targets.h"
#include "ir/module.h"

namespace smachac::backends::flexbe {

/// The generator's output of every behavior, the script's first, then the embedded ones in
/// the order they were first met; nullopt after errors.
std::optional<std::vector<std::string>> writeBehaviors(const ir::Module& module,
                                                       generator::GeneratorContext& context);

}  // namespace smachac::backends::flexbe
