#pragma once
// Counts loop iterations over 1 s wall-clock windows: AMBF's "dynamic loop frequency" (Phx).

#include <chrono>
#include <cstdint>

namespace ambf_like {

/// Iterations per second, measured over consecutive windows of one second of wall time.
class FrequencyMeter {
 public:
  using Clock = std::chrono::steady_clock;

  explicit FrequencyMeter(Clock::duration window = std::chrono::seconds(1)) : window_(window) {}

  /// Counts one iteration at `now`; returns true when this tick closed a window.
  bool tick(Clock::time_point now = Clock::now());

  /// Rate over the last completed window (0 until one completes).
  double frequency() const { return last_; }
  double minimum() const { return min_; }
  double maximum() const { return max_; }
  std::uint64_t completedWindows() const { return windows_; }
  /// All iterations counted so far.
  std::uint64_t iterations() const { return total_; }

 private:
  Clock::duration window_;
  Clock::time_point window_start_{};
  bool started_ = false;
  std::uint64_t in_window_ = 0;
  std::uint64_t total_ = 0;
  std::uint64_t windows_ = 0;
  double last_ = 0.0;
  double min_ = 0.0;
  double max_ = 0.0;
};

}  // namespace ambf_like
