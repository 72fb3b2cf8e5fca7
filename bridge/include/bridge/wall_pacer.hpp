#pragma once
// Keeps a loop on the wall clock: platform time t is due at wall time epoch + t.

#include <chrono>
#include <optional>

namespace bridge {

/// Sleeps until platform times fall due. The first call anchors the epoch; a loop that falls
/// more than `max_lag` behind is re-anchored rather than left to race to catch up.
class WallPacer {
 public:
  explicit WallPacer(double max_lag = 0.1) : max_lag_(max_lag) {}
  /// Returns when `platform_time` is due (at once if it is already past).
  void waitUntil(double platform_time);
  /// Wall seconds since the epoch (0 before the first call).
  double elapsed() const;

 private:
  using Clock = std::chrono::steady_clock;
  std::optional<Clock::time_point> epoch_;
  double max_lag_;
};

}  // namespace bridge
