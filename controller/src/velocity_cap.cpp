#include "controller/velocity_cap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace controller {

double InterpolationPlan::progress(int k) const {
  return k == 0 ? 0.0 : std::min(static_cast<double>(k - 1) + lead, static_cast<double>(steps));
}

ArmPair InterpolationPlan::increment(int k) const {
  const double share = progress(k) - progress(k - 1);
  if (share == 1.0) return {delta[0] / steps, delta[1] / steps};
  return {share / steps * delta[0], share / steps * delta[1]};
}

ArmPair InterpolationPlan::at(int k) const {
  const double s = progress(k) / steps;
  return {start[0] + s * delta[0], start[1] + s * delta[1]};
}

InterpolationPlan planMove(const ArmPair& start, const ArmPair& next, const VelocityCaps& caps,
                           double step_period, double lead) {
  if (!(lead > 0.0 && lead <= 1.0)) {
    throw std::invalid_argument("planMove: the first command's share of a step must be in (0, 1]");
  }
  InterpolationPlan plan{start, {next[0] - start[0], next[1] - start[1]}, 0, lead};
  const raven::ArmJoints cap = caps.perStep(step_period);
  double ratio = 0.0;
  for (const auto& d : plan.delta)
    ratio = std::max(ratio, d.cwiseAbs().cwiseQuotient(cap).maxCoeff());
  const int n = static_cast<int>(std::min(ratio, 1e8)) + 1;  // (targets are finite and bounded)
  plan.steps = std::max(n, caps.min_steps);
  return plan;
}

}  // namespace controller
