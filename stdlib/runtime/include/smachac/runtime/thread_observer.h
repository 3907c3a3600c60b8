// ThreadObserver: told when a Concurrence splits a machine's thread into one per child and
// joins them again, for code that must know how many threads of a machine run at once — a
// simulator that advances simulated time in lockstep with every running branch, say, so that
// a child thread that starts late does not find the others ahead of it.
//
// For a Concurrence of n children the calls are: split(n) before any child starts (the calling
// thread's place passes to the children: n threads now run instead of one), returned() once
// per child, on the child's thread, after it finished (normally, by preemption or with an
// exception), and joined() on the calling thread when it resumes. Calls come from several
// threads: an observer serialises itself.
#pragma once

#include <cstddef>

namespace smachac::runtime {

class ThreadObserver {
 public:
  virtual ~ThreadObserver() = default;
  virtual void split(std::size_t children) = 0;
  virtual void returned() = 0;
  virtual void joined() = 0;
};

}  // namespace smachac::runtime
