// smachac's entry point: normalises the command line, picks the subcommand, and runs it on a
// thread with a large stack (deeply nested input must give a diagnostic, not a crash).
#include <malloc.h>
#include <pthread.h>

#include <cstdio>
#include <string_view>

#include "tools/smachac/args.h"
#include "tools/smachac/commands.h"

namespace {

using smachac::driver::Args;

struct Command {
  std::string_view word;
  int (*run)(const Args&);
};

constexpr Command kCommands[] = {
#define SMACHAC_COMMAND(word, function, help) {word, &smachac::driver::function},
#include "tools/smachac/commands.def"
};

struct Job {
  Args args;
  int exit_code = smachac::driver::kExitUsageError;
};

int dispatch(const Args& args) {
  for (const Command& command : kCommands) {
    if (!args.empty() && args.front() == command.word) {
      return command.run(Args(args.begin() + 1, args.end()));
    }
  }
  return smachac::driver::runCompile(args);
}

void* runJob(void* raw) {
  Job* job = static_cast<Job*>(raw);
  job->exit_code = dispatch(job->args);
  return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  // One malloc arena: the job thread allocates from the main thread's (which waits) rather
  // than mapping an arena of its own and handing it back at exit.
  mallopt(M_ARENA_MAX, 1);
  Job job{smachac::driver::normalizeArgs(Args(argv + 1, argv + argc))};
  constexpr size_t kStackBytes = size_t{1} << 30;  // reserved, not committed
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, kStackBytes);
  pthread_t thread;
  if (pthread_create(&thread, &attr, &runJob, &job) != 0) {
    runJob(&job);
  } else {
    pthread_join(thread, nullptr);
  }
  pthread_attr_destroy(&attr);
  std::fflush(stdout);
  return job.exit_code;
}
