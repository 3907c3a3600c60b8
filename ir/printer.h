// The stable text form of the IR (`smachac -target=ir`, *.ir golden files). One line per
// state header (kind, name, template, location), then its fields, two spaces per level:
//
//   base SEQ template=Base @1:1
//     outcomes: [done]
//     leaf FOO template=ParamFoo @5:5
//       transitions: {outcome_a -> done (outcome)}
//
// Locations print as @line:col, prefixed by the file name when it is not the main script.
#pragma once

#include <string>

#include "ir/module.h"
#include "ir/support/source_manager.h"

namespace smachac::ir {

std::string printModule(const Module& module, const SourceManager& sources);

}  // namespace smachac::ir
