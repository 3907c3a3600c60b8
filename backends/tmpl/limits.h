// The bounds that keep any template's render finite: execution steps (loop iterations and
// calls, plus one step per 256 bytes of every string and list the render creates, so that
// neither loops nor ever larger values can run unbounded), the size of any one string (and of
// the output) and of any one list or dict. Each Environment has its own
// (Environment::setLimits); a render installs them for its thread.
#pragma once

#include <cstddef>
#include <cstdint>

namespace smachac::tmpl {

struct Limits {
  uint64_t steps = 50'000'000;
  size_t string_bytes = size_t{256} << 20;
  size_t items = size_t{1} << 22;
};

/// The limits of the render running on this thread (the defaults outside any render).
const Limits& activeLimits();

/// Bytes of created values that count as one execution step.
constexpr size_t kBytesPerStep = 256;

/// chargeWork for a value of at least kBytesPerStep bytes.
void chargeLargeWork(size_t bytes);

/// Charges creating `bytes` bytes of values to the running render's steps; raises Fault when
/// they exceed the limit. Outside a render it does nothing. Inline: most values are small
/// and cost nothing.
inline void chargeWork(size_t bytes) {
  if (bytes >= kBytesPerStep) chargeLargeWork(bytes);
}

/// Raises Fault when `steps` exceed the active limit.
void checkSteps(uint64_t steps);

/// Makes `limits` and the render's step counter the active ones on this thread while alive,
/// then restores the previous ones (renders may nest).
class ScopedLimits {
 public:
  ScopedLimits(const Limits& limits, uint64_t& steps);
  ~ScopedLimits();
  ScopedLimits(const ScopedLimits&) = delete;
  ScopedLimits& operator=(const ScopedLimits&) = delete;

 private:
  const Limits* previous_limits_;
  uint64_t* previous_steps_;
};

}  // namespace smachac::tmpl
