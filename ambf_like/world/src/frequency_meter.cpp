#include "ambf_like/frequency_meter.hpp"

#include <algorithm>

namespace ambf_like {

bool FrequencyMeter::tick(Clock::time_point now) {
  ++total_;
  if (!started_) {  // the first tick opens the first window; iterations are counted after it
    started_ = true;
    window_start_ = now;
    return false;
  }
  ++in_window_;
  const auto elapsed = now - window_start_;
  if (elapsed < window_) return false;
  last_ = static_cast<double>(in_window_) / std::chrono::duration<double>(elapsed).count();
  min_ = windows_ == 0 ? last_ : std::min(min_, last_);
  max_ = windows_ == 0 ? last_ : std::max(max_, last_);
  ++windows_;
  in_window_ = 0;
  window_start_ = now;
  return true;
}

}  // namespace ambf_like
