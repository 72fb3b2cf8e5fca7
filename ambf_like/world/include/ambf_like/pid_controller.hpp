#pragma once
// A PID controller on a scalar error, advanced with the simulation's fixed step.

#include "ambf_like/joint_spec.hpp"

namespace ambf_like {

/// PID on the error (setpoint - measured), derivative of the error, as AMBF's joint controller.
class PidController {
 public:
  explicit PidController(PidGains gains = {}) : gains_(gains) {}

  double update(double error, double dt) {
    integral_ += error * dt;
    const double derivative = has_previous_ ? (error - previous_error_) / dt : 0.0;
    previous_error_ = error;
    has_previous_ = true;
    return gains_.p * error + gains_.i * integral_ + gains_.d * derivative;
  }

  void reset() {
    integral_ = 0.0;
    previous_error_ = 0.0;
    has_previous_ = false;
  }

  const PidGains& gains() const { return gains_; }

 private:
  PidGains gains_;
  double integral_ = 0.0;
  double previous_error_ = 0.0;
  bool has_previous_ = false;
};

}  // namespace ambf_like
