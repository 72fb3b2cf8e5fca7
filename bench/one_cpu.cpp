#include "one_cpu.hpp"

#include <spdlog/spdlog.h>

#include <cerrno>
#include <cstring>

namespace bench {

OneCpu::OneCpu() {
  CPU_ZERO(&before_);
  if (sched_getaffinity(0, sizeof before_, &before_) != 0) {
    spdlog::warn("cannot read this thread's CPUs ({}); it is not pinned", std::strerror(errno));
    return;
  }
  for (int c = 0; c < CPU_SETSIZE; ++c) {
    if (!CPU_ISSET(c, &before_)) continue;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(c, &one);
    if (sched_setaffinity(0, sizeof one, &one) == 0) cpu_ = c;
    break;
  }
  if (cpu_ < 0) spdlog::warn("cannot pin this thread to one CPU; it runs where it did");
}

OneCpu::~OneCpu() {
  if (cpu_ >= 0) sched_setaffinity(0, sizeof before_, &before_);
}

}  // namespace bench
