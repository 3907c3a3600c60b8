// runOnLargeStack: by default the job switches to a mapped stack on the calling thread
// (makecontext/swapcontext), where a thread of its own cost a cold compile about 50 us of CPU
// time in clone, scheduling and teardown. Sanitizer builds define SMACHAC_SANITIZED and keep
// a thread: AddressSanitizer cannot follow a switched stack through a thrown exception.
#include "tools/smachac/large_stack.h"

#ifdef SMACHAC_SANITIZED
#include <pthread.h>
#else
#include <sys/mman.h>
#include <ucontext.h>
#include <unistd.h>
#endif

namespace smachac::driver {
namespace {

struct PendingJob {
  void (*job)(void*) = nullptr;
  void* arg = nullptr;
};

#ifdef SMACHAC_SANITIZED

void* runPending(void* raw) {
  const PendingJob* pending = static_cast<const PendingJob*>(raw);
  pending->job(pending->arg);
  return nullptr;
}

/// Runs the job on a thread with the large stack; false when no thread could be made.
bool runOnOwnStack(PendingJob& pending) {
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, kLargeStackBytes);
  pthread_t thread;
  const bool started = pthread_create(&thread, &attr, &runPending, &pending) == 0;
  if (started) pthread_join(thread, nullptr);
  pthread_attr_destroy(&attr);
  return started;
}

#else

// makecontext passes int arguments only: the entry point reads the job from here.
PendingJob g_pending;

void runPending() { g_pending.job(g_pending.arg); }

/// Runs the job on a mapped stack whose lowest page is a guard; false when the address space
/// could not be mapped.
bool runOnOwnStack(PendingJob& pending) {
  const size_t guard = static_cast<size_t>(sysconf(_SC_PAGESIZE));
  const size_t total = kLargeStackBytes + guard;
  void* base = mmap(nullptr, total, PROT_READ | PROT_WRITE,
                    MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE | MAP_STACK, -1, 0);
  if (base == MAP_FAILED) return false;
  mprotect(base, guard, PROT_NONE);
  g_pending = pending;
  ucontext_t caller;
  ucontext_t job;
  getcontext(&job);
  job.uc_stack.ss_sp = static_cast<char*>(base) + guard;
  job.uc_stack.ss_size = kLargeStackBytes;
  job.uc_link = &caller;
  makecontext(&job, &runPending, 0);
  swapcontext(&caller, &job);
  munmap(base, total);
  return true;
}

#endif

}  // namespace

void runOnLargeStack(void (*job)(void*), void* arg) {
  PendingJob pending{job, arg};
  if (!runOnOwnStack(pending)) job(arg);
}

}  // namespace smachac::driver
