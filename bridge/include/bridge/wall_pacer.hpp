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
  /// Wall seconds until `platform_time` is due (<= 0: it is due).
  double secondsUntil(double platform_time);

 private:
  using Clock = std::chrono::steady_clock;
  std::optional<Clock::time_point> epoch_;
  double max_lag_;
};

}  // namespace bridge
