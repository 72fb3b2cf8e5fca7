#include "scenario/handover_reach.hpp"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <limits>
#include <random>

#include "raven/arm_kinematics.hpp"

namespace scenario {

std::string HandoverReach::explain(double jaw_length) const {
  if (possible(jaw_length)) {
    return fmt::format("possible: the workspaces come within {:.3f} m along x", gap());
  }
  return fmt::format(
      "impossible: over {} sampled joint vectors per arm the left tool point never goes below "
      "x = {:.3f} m and the right never above x = {:.3f} m, so the graspers stay {:.3f} m apart",
      samples_per_arm, left_min_x, right_max_x, gap());
}

HandoverReach measureHandoverReach(const raven::PlatformProfile& profile, std::size_t samples,
                                   std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const raven::JointLimits& limits = profile.limits;
  auto extremeX = [&](raven::Arm arm, bool smallest) {
    const auto kinematics = raven::ArmKinematics::of(profile, arm);
    double extreme = smallest ? std::numeric_limits<double>::infinity()
                              : -std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < samples; ++s) {
      raven::ArmJoints q;
      for (int j = 0; j < raven::kJointCount; ++j) {
        q[j] = limits.low[j] + unit(random) * (limits.high[j] - limits.low[j]);
      }
      const double x = kinematics.toolPose(q).translation().x();
      extreme = smallest ? std::min(extreme, x) : std::max(extreme, x);
    }
    return extreme;
  };
  HandoverReach reach;
  reach.samples_per_arm = samples;
  reach.left_min_x = extremeX(raven::Arm::Left, true);
  reach.right_max_x = extremeX(raven::Arm::Right, false);
  return reach;
}

}  // namespace scenario
