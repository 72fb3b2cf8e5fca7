#pragma once
// A RavenPlatform decorator that timestamps the servo_jr commands leaving the controller, for
// measuring its command rate, period jitter and input latency.

#include <chrono>
#include <mutex>
#include <vector>

#include "bridge/raven_platform.hpp"

namespace bench {

/// Forwards everything to `inner`; records when each servo_jr was sent, for which arm, and
/// whether it moved anything.
class StampingPlatform final : public bridge::RavenPlatform {
 public:
  using Clock = std::chrono::steady_clock;
  struct Stamp {
    Clock::time_point at;
    bridge::Arm arm;
    bool moves = false;
  };

  explicit StampingPlatform(bridge::RavenPlatform& inner) : inner_(inner) {}

  bridge::CommandResult send(const bridge::PlatformCommand& command) override;
  bridge::OperatingStatus operatingStatus() const override { return inner_.operatingStatus(); }
  bridge::JointSample measuredJs(bridge::Arm arm) const override { return inner_.measuredJs(arm); }
  bridge::JointSample setpointJs(bridge::Arm arm) const override { return inner_.setpointJs(arm); }
  bridge::PoseSample measuredCp(bridge::Arm arm) const override { return inner_.measuredCp(arm); }
  bridge::PoseSample setpointCp(bridge::Arm arm) const override { return inner_.setpointCp(arm); }
  std::optional<bridge::RavenStateSnapshot> ravenState() const override {
    return inner_.ravenState();
  }
  bridge::ClockKind clockKind() const override { return inner_.clockKind(); }
  double now() const override { return inner_.now(); }
  void advance(double seconds) override { inner_.advance(seconds); }

  /// Every stamp so far (a copy: the command thread keeps adding).
  std::vector<Stamp> stamps() const;
  void clear();

 private:
  bridge::RavenPlatform& inner_;
  mutable std::mutex mutex_;
  std::vector<Stamp> stamps_;
};

}  // namespace bench
