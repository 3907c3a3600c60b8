// Where the MJCF models live: the source tree's sim/models by default (compiled in), or the
// directory named by the environment variable SMACHAC_SIM_MODEL_DIR.
#pragma once

#include <string>

namespace smachac::sim {

/// The model directory: $SMACHAC_SIM_MODEL_DIR when set and non-empty, else sim/models.
std::string modelDirectory();

/// modelDirectory() + "/scene.xml": Baxter, the table and three blocks.
std::string defaultScenePath();

}  // namespace smachac::sim
