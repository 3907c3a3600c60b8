// smachac's entry point: normalises the command line, picks the subcommand, and runs it on a
// large stack (large_stack.h: deeply nested input must give a diagnostic, not a crash).
#include <malloc.h>

#include <string_view>

#include "tools/smachac/args.h"
#include "tools/smachac/commands.h"
#include "tools/smachac/huge_pages.h"
#include "tools/smachac/large_stack.h"
#include "tools/smachac/process_exit.h"
#include "tools/smachac/small_object_heap.h"

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

void runJob(void* raw) {
  Job* job = static_cast<Job*>(raw);
  job->exit_code = dispatch(job->args);
}

}  // namespace

int main(int argc, char** argv) {
  // One malloc arena: a job thread (sanitizer builds) allocates from the main thread's
  // (which waits) rather than mapping an arena of its own and handing it back at exit.
  mallopt(M_ARENA_MAX, 1);
  // Blocks of 1 MiB and more get mappings of their own, always (glibc raises the threshold as
  // such blocks are freed): a big script's code buffers and output then grow and shrink
  // without leaving freed pages inside the heap. The 100,000-state compile peaks at 123 MB
  // instead of 145 (256 KiB: the same peak, 18% more page faults).
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(smachac::driver::kMappedBlockBytes));
  // Every command but the language server (whose threads share documents) runs on one thread.
  if (argc < 2 || std::string_view(argv[1]) != "lsp") smachac::driver::enableSmallObjectHeap();
  Job job{smachac::driver::normalizeArgs(Args(argv + 1, argv + argc))};
  smachac::driver::runOnLargeStack(&runJob, &job);
  return smachac::driver::finishProcess(job.exit_code);
}
