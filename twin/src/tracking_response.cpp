#include "twin/tracking_response.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace twin {

namespace {

using raven::ArmJoints;

/// "bandwidth_hz[2] must be > 0, not -1", or empty.
std::string checkJoints(const char* field, const ArmJoints& values, bool infinite_allowed) {
  for (int j = 0; j < raven::kJointCount; ++j) {
    const double v = values(j);
    if (std::isnan(v) || v <= 0.0 || (!infinite_allowed && std::isinf(v))) {
      return std::string(field) + "[" + std::to_string(j) + "] (" +
             std::string(raven::kJointNames[static_cast<std::size_t>(j)]) + ") must be " +
             (infinite_allowed ? "> 0 (or infinite)" : "finite and > 0") + ", not " +
             std::to_string(v);
    }
  }
  return {};
}

/// "friction_deadband[2] (insertion) must be finite and >= 0, not -1", or empty.
std::string checkNonNegative(const char* field, const ArmJoints& values) {
  for (int j = 0; j < raven::kJointCount; ++j) {
    if (!(values(j) >= 0.0 && std::isfinite(values(j)))) {
      return std::string(field) + "[" + std::to_string(j) + "] (" +
             std::string(raven::kJointNames[static_cast<std::size_t>(j)]) +
             ") must be finite and >= 0, not " + std::to_string(values(j));
    }
  }
  return {};
}

}  // namespace

std::string TrackingParams::invalidReason() const {
  if (!(latency_cycles >= 0.0 && latency_cycles <= kMaxLatencyCycles)) {
    return "latency_cycles must be within 0.." + std::to_string(kMaxLatencyCycles) + ", not " +
           std::to_string(latency_cycles);
  }
  for (const auto& reason : {checkJoints("bandwidth_hz", bandwidth_hz, true),
                             checkJoints("damping_ratio", damping_ratio, false),
                             checkNonNegative("friction_deadband", friction_deadband),
                             checkJoints("max_velocity", max_velocity, true),
                             checkJoints("max_acceleration", max_acceleration, true)}) {
    if (!reason.empty()) return reason;
  }
  return {};
}

TrackingActuation::TrackingActuation(std::unique_ptr<Actuation> inner, const TrackingParams& params,
                                     double cycle)
    : inner_(std::move(inner)), params_(params), cycle_(cycle) {
  if (const auto why = params_.invalidReason(); !why.empty()) {
    throw std::invalid_argument("tracking response: " + why);
  }
}

ArmJoints TrackingActuation::delayed(const ArmState& s) const {
  const double latency = params_.latency_cycles;
  const auto whole = static_cast<std::size_t>(latency);
  const double fraction = latency - static_cast<double>(whole);
  const std::size_t last = s.history.size() - 1;
  const ArmJoints& newer = s.history[std::min(whole, last)];
  const ArmJoints& older = s.history[std::min(whole + 1, last)];
  return (1.0 - fraction) * newer + fraction * older;
}

void TrackingActuation::respond(ArmState& s, const ArmJoints& reference) const {
  const double dt = cycle_;
  for (int j = 0; j < raven::kJointCount; ++j) {
    double v = 0.0;
    if (std::isinf(params_.bandwidth_hz(j))) {
      v = (reference(j) - s.position(j)) / dt;
    } else {
      // Backward Euler on x'' = w^2 (r - x) - 2 zeta w x' - f sign(x'): stable at any bandwidth.
      const double w = 2.0 * M_PI * params_.bandwidth_hz(j);
      const double zeta = params_.damping_ratio(j);
      const double drive = w * w * (reference(j) - s.position(j));
      const double friction = params_.friction_deadband(j) * w * w;
      const double was = s.velocity(j);
      if (was == 0.0 && std::abs(drive) <= friction) {
        v = 0.0;  // stuck: the servo's pull does not overcome static friction
      } else {
        const double direction = was != 0.0 ? std::copysign(1.0, was) : std::copysign(1.0, drive);
        v = (was + dt * (drive - friction * direction)) /
            (1.0 + 2.0 * zeta * w * dt + w * w * dt * dt);
        // Friction stops the joint (it never reverses it), and holds it once it could bring it
        // to rest within the cycle while the servo's pull is at breakaway (the slide approaches
        // it only asymptotically: within 0.1 %).
        const bool stops = std::abs(v) < friction * dt && std::abs(drive) <= 1.001 * friction;
        if (v * direction < 0.0 || stops) v = 0.0;
      }
    }
    const double dv = params_.max_acceleration(j) * dt;
    v = std::clamp(v, s.velocity(j) - dv, s.velocity(j) + dv);
    v = std::clamp(v, -params_.max_velocity(j), params_.max_velocity(j));
    s.velocity(j) = v;
    s.position(j) += dt * v;
  }
}

void TrackingActuation::drive(raven::Arm arm, const ArmJoints& setpoint,
                              const ArmJoints& /*setpoint_velocity*/) {
  ArmState& s = arms_[static_cast<std::size_t>(raven::index(arm))];
  if (s.history.empty()) s.position = setpoint;  // at rest where the robot starts
  s.history.push_front(setpoint);
  const auto kept = static_cast<std::size_t>(params_.latency_cycles) + 2;
  while (s.history.size() > kept) s.history.pop_back();
  respond(s, delayed(s));
  inner_->drive(arm, s.position, s.velocity);
}

}  // namespace twin
