// Runs a job on a large stack, so that deeply nested input ends in a diagnostic rather than a
// stack overflow. Rules: the job runs to completion before runOnLargeStack returns; it must
// not let an exception escape; the stack is reserved address space, committed page by page.
#pragma once

#include <cstddef>

namespace smachac::driver {

/// Bytes of address space reserved for the job's stack.
inline constexpr std::size_t kLargeStackBytes = std::size_t{1} << 30;

/// Calls `job(arg)` on a stack of kLargeStackBytes (on the caller's own stack when the
/// address space cannot be had).
void runOnLargeStack(void (*job)(void*), void* arg);

}  // namespace smachac::driver
