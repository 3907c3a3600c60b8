// Locates sim/models: an environment override, else the directory compiled in by CMake.
#include "smachac/sim/model_path.h"

#include <cstdlib>

#ifndef SMACHAC_SIM_MODEL_DIR_DEFAULT
#error "SMACHAC_SIM_MODEL_DIR_DEFAULT must be defined by sim/CMakeLists.txt"
#endif

namespace smachac::sim {

std::string modelDirectory() {
  const char* from_environment = std::getenv("SMACHAC_SIM_MODEL_DIR");
  if (from_environment != nullptr && *from_environment != '\0') return from_environment;
  return SMACHAC_SIM_MODEL_DIR_DEFAULT;
}

std::string defaultScenePath() { return modelDirectory() + "/scene.xml"; }

}  // namespace smachac::sim
