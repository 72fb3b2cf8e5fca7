#include "bridge/wall_pacer.hpp"

#include <spdlog/spdlog.h>

#include <thread>

namespace bridge {

void WallPacer::waitUntil(double platform_time) {
  const auto now = Clock::now();
  const auto offset =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(platform_time));
  if (!epoch_) epoch_ = now - offset;
  const auto due = *epoch_ + offset;
  const double late = std::chrono::duration<double>(now - due).count();
  if (late > max_lag_) {
    spdlog::warn("{:.0f} ms behind the wall clock; carrying on from now", late * 1e3);
    epoch_ = now - offset;
    return;
  }
  std::this_thread::sleep_until(due);
}

double WallPacer::elapsed() const {
  return epoch_ ? std::chrono::duration<double>(Clock::now() - *epoch_).count() : 0.0;
}

}  // namespace bridge
