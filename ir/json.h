// The JSON form of the IR (`smachac -target=json`): the state tree with every field, typed
// values and source locations. Schema (version 1):
//   {"format": "smachac-ir", "version": 1, "files": [paths], "root": <state>}
//   <state> = {"kind", "name", "loc", "template"?, "outcomes"?, ..., "states"?: [<state>]}
//   <name>  = {"text", "loc"};  <loc> = {"file": index into files, "line", "column"}
//   <value> = {"type": "list<int>", "value": JSON value; expressions as {"expression": code},
//             non-finite floats as {"float": "nan"|"inf"|"-inf"}}
#pragma once

#include <string>

#include "ir/module.h"
#include "ir/support/source_manager.h"

namespace smachac::ir {

std::string moduleToJson(const Module& module, const SourceManager& sources);

}  // namespace smachac::ir
