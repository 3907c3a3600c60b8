// Captures MuJoCo's warning text (mju_user_warning) in memory instead of MuJoCo's default of
// printing it and appending it to MUJOCO_LOG.TXT in the working directory.
#include <mujoco/mujoco.h>

#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "smachac/sim/world.h"

namespace smachac::sim {
namespace {

std::mutex messages_mutex;
std::vector<std::string> messages;  // NOLINT: process-wide, as MuJoCo's hook is

void collectWarning(const char* text) {
  std::lock_guard lock(messages_mutex);
  messages.emplace_back(text);
}

}  // namespace

namespace detail {

void installMujocoMessageHook() {
  static std::once_flag installed;
  std::call_once(installed, [] { mju_user_warning = &collectWarning; });
}

}  // namespace detail

std::vector<std::string> takeMujocoMessages() {
  std::lock_guard lock(messages_mutex);
  return std::exchange(messages, {});
}

}  // namespace smachac::sim
