#include "bridge/command_checks.hpp"

#include <cmath>
#include <sstream>

namespace bridge {

namespace {

std::string jointName(int i) {
  return std::string(raven::kJointNames[static_cast<std::size_t>(i)]);
}

}  // namespace

const char* jointUnit(int joint) {
  return joint == raven::kInsertion ? "m" : "rad";
}

std::optional<std::string> nonFiniteJoint(const raven::ArmJoints& q) {
  for (int i = 0; i < raven::kJointCount; ++i) {
    if (!std::isfinite(q(i))) return "joint '" + jointName(i) + "' is NaN or infinite";
  }
  return std::nullopt;
}

std::optional<std::string> jumpRefusal(const raven::ArmJoints& goal, const raven::ArmJoints& from,
                                       const ServoLimits& limits) {
  const raven::ArmJoints max_jump = limits.maxJump();
  for (int i = 0; i < raven::kJointCount; ++i) {
    const double jump = std::abs(goal(i) - from(i));
    if (jump > max_jump(i) * (1.0 + 1e-9)) {
      std::ostringstream why;
      why << "joint '" << jointName(i) << "' would jump " << jump << " " << jointUnit(i)
          << ", more than " << limits.jump_cycles << " cycles of motion (" << max_jump(i) << " "
          << jointUnit(i) << ")";
      return why.str();
    }
  }
  return std::nullopt;
}

}  // namespace bridge
