#include "controller/velocity_cap.hpp"

#include <algorithm>
#include <cmath>

namespace controller {

ArmPair InterpolationPlan::increment() const {
  return {delta[0] / steps, delta[1] / steps};
}

ArmPair InterpolationPlan::at(int k) const {
  const double s = static_cast<double>(k) / steps;
  return {start[0] + s * delta[0], start[1] + s * delta[1]};
}

InterpolationPlan planMove(const ArmPair& start, const ArmPair& next, const VelocityCaps& caps,
                           double step_period) {
  InterpolationPlan plan{start, {next[0] - start[0], next[1] - start[1]}, 0};
  const raven::ArmJoints cap = caps.perStep(step_period);
  double ratio = 0.0;
  for (const auto& d : plan.delta)
    ratio = std::max(ratio, d.cwiseAbs().cwiseQuotient(cap).maxCoeff());
  const int n = static_cast<int>(std::min(ratio, 1e8)) + 1;  // (targets are finite and bounded)
  plan.steps = std::max(n, caps.min_steps);
  return plan;
}

}  // namespace controller
