#pragma once
// The physical robot's tracking behaviour, placed in front of any actuation: each joint's
// setpoint reaches the servo a latency later and through a second-order response (natural
// frequency, damping ratio, Coulomb friction that makes small motions stick) under velocity and
// acceleration limits. Off unless a calibration
// (raven_calibrate's profile, loaded with --calibration) asks for it.

#include <deque>
#include <limits>
#include <memory>
#include <string>

#include "twin/actuation.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// The response's parameters, per joint in raven::ArmJoints order (joint units: rad, m).
struct TrackingParams {
  /// Robot cycles between a setpoint and the servo seeing it; fractional values interpolate
  /// between the two neighbouring cycles' setpoints.
  double latency_cycles = 0.0;
  /// Natural frequency of each joint's response (Hz); infinite: the setpoint passes straight on.
  raven::ArmJoints bandwidth_hz = raven::ArmJoints::Constant(kUnlimited);
  raven::ArmJoints damping_ratio = raven::ArmJoints::Constant(1.0);
  /// Coulomb friction, as the position error the servo needs to break the joint away from rest
  /// (and holds against while the joint slides): friction = deadband * (2 pi bandwidth)^2.
  raven::ArmJoints friction_deadband = raven::ArmJoints::Zero();
  raven::ArmJoints max_velocity = raven::ArmJoints::Constant(kUnlimited);      ///< per s
  raven::ArmJoints max_acceleration = raven::ArmJoints::Constant(kUnlimited);  ///< per s^2

  static constexpr double kUnlimited = std::numeric_limits<double>::infinity();
  /// The longest latency accepted (cycles).
  static constexpr double kMaxLatencyCycles = 100.0;

  /// Why these values cannot be used (naming the field), or empty when they can.
  std::string invalidReason() const;
};

/// Shapes each arm's setpoints by TrackingParams, then hands them to another actuation.
class TrackingActuation final : public Actuation {
 public:
  /// Throws std::invalid_argument when `params` are invalid. `cycle`: the robot's period (s).
  TrackingActuation(std::unique_ptr<Actuation> inner, const TrackingParams& params, double cycle);
  void drive(raven::Arm arm, const raven::ArmJoints& setpoint,
             const raven::ArmJoints& setpoint_velocity) override;
  ActuatorReadings read(raven::Arm arm) const override { return inner_->read(arm); }

 private:
  /// One arm's delay line and response state (starts at rest on the first setpoint).
  struct ArmState {
    std::deque<raven::ArmJoints> history;  ///< newest first
    raven::ArmJoints position = raven::ArmJoints::Zero();
    raven::ArmJoints velocity = raven::ArmJoints::Zero();
  };
  raven::ArmJoints delayed(const ArmState& s) const;
  void respond(ArmState& s, const raven::ArmJoints& reference) const;

  std::unique_ptr<Actuation> inner_;
  TrackingParams params_;
  double cycle_;
  std::array<ArmState, 2> arms_;
};

}  // namespace twin
