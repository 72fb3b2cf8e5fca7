#pragma once
// The paper's velocity cap C_V: a move of both arms is split into at least ten equal steps, more
// when a joint would otherwise exceed its speed cap.

#include <array>

#include "raven/arm.hpp"

namespace controller {

using raven::ArmPair;

/// Joint speed caps (rad/s, m/s for the insertion): 5 deg/s on joints 1-2, 0.02 m/s on the
/// insertion, 15 deg/s on joints 4-7 (MAX_JR of the reference at 500 steps a second).
struct VelocityCaps {
  raven::ArmJoints per_second =
      (raven::ArmJoints() << 5.0, 5.0, 0.0, 15.0, 15.0, 15.0, 15.0).finished() * (M_PI / 180.0) +
      raven::ArmJoints::Unit(raven::kInsertion) * 0.02;
  int min_steps = 10;  ///< "man_steps"

  /// The largest increment one step of `step_period` seconds may carry.
  raven::ArmJoints perStep(double step_period) const { return per_second * step_period; }
};

/// A move from `start` to `start + delta` in `steps` equal steps.
struct InterpolationPlan {
  ArmPair start;
  ArmPair delta;
  int steps = 0;

  /// Each step's increment (delta / steps).
  ArmPair increment() const;
  /// Where the arms are after `k` steps (start + k / steps * delta).
  ArmPair at(int k) const;
};

/// n = int(max over arms and joints |delta_j| / cap_j) + 1; steps = max(n, min_steps).
InterpolationPlan planMove(const ArmPair& start, const ArmPair& next, const VelocityCaps& caps,
                           double step_period);

}  // namespace controller
