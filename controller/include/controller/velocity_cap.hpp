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

/// A move from `start` to `start + delta` in `steps` equal steps of one period each. When the
/// move's first command follows the previous one by less than a period (`lead` of a period: the
/// pad changed mid-period), that command carries only `lead` of a step and one more command
/// finishes the move, so that no command moves faster than the caps over its own time.
struct InterpolationPlan {
  ArmPair start;
  ArmPair delta;
  int steps = 0;
  double lead = 1.0;

  /// The commands the move takes: `steps`, one more after a short first one.
  int commands() const { return lead < 1.0 ? steps + 1 : steps; }
  /// Command k's increment (delta / steps, `lead` of it for the first command, the rest of
  /// a step for the last).
  ArmPair increment(int k) const;
  /// Where the arms are after `k` commands (start + progress / steps * delta).
  ArmPair at(int k) const;

 private:
  /// Steps' worth of the move done after `k` commands.
  double progress(int k) const;
};

/// n = int(max over arms and joints |delta_j| / cap_j) + 1; steps = max(n, min_steps). `lead`
/// in (0, 1]: the share of a period since the previous command.
InterpolationPlan planMove(const ArmPair& start, const ArmPair& next, const VelocityCaps& caps,
                           double step_period, double lead = 1.0);

}  // namespace controller
