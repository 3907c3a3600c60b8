// Locates sim/models: an environment override, else the directory compiled in by CMake.
#include "smachac/sim/model_path.h"

#include <cstdlib>

#ifndef SMACHAC_SIM_MODEL_DIR_DEFAULT
#error "SMACHAC_SIM_MODEL_DIR_DEFAULT must be defined by sim/CMakeLists.txt"
#endif

namespace smachac::sim {

auto modelDirectory() -> std::string {
  const char* fromEnvironment = std::getenv("SMACHAC_SIM_MODEL_DIR");
  if (fromEnvironment != nullptr && *fromEnvironment != '\0') return fromEnvironment;
  return SMACHAC_SIM_MODEL_DIR_DEFAULT;
}

auto defaultScenePath() -> std::string { return modelDirectory() + "/scene.xml"; }

}  // namespace smachac::sim
