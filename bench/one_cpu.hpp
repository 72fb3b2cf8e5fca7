#pragma once
// Keeps the calling thread, and the programs it starts, on one CPU while in scope.

#include <sched.h>

namespace bench {

/// Pins the calling thread to the first CPU it may run on and restores its set when destroyed.
/// Programs it forks meanwhile inherit the pin. On a VM whose CPUs run at different speeds (this
/// project's 2-core host: one runs the same steps some 25 % slower than the other), rows taken
/// on whichever CPU the scheduler chose are not comparable; on one CPU they are.
class OneCpu {
 public:
  OneCpu();
  ~OneCpu();
  OneCpu(const OneCpu&) = delete;
  OneCpu& operator=(const OneCpu&) = delete;
  /// The CPU the thread is held on (-1: the pin failed and the thread runs where it did).
  int cpu() const { return cpu_; }

 private:
  cpu_set_t before_;
  int cpu_ = -1;
};

}  // namespace bench
