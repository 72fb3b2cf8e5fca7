#pragma once
// The value checks a servo command must pass, shared by the robot's core and by clients that
// must not send what the robot would refuse.

#include <optional>
#include <string>

#include "bridge/servo_limits.hpp"
#include "raven/arm.hpp"

namespace bridge {

/// "joint 'wrist' is NaN or infinite" for the first such joint, if any.
std::optional<std::string> nonFiniteJoint(const raven::ArmJoints& q);

/// Why `goal` is too far from `from` for one servo command (more than the limits' jump window
/// on some joint), if it is.
std::optional<std::string> jumpRefusal(const raven::ArmJoints& goal, const raven::ArmJoints& from,
                                       const ServoLimits& limits);

/// "rad", or "m" for the insertion.
const char* jointUnit(int joint);

}  // namespace bridge
